//! The browser's shelf: one `localStorage` key per entry, `onemorebrick/NAME` (the desktop's
//! file names). `localStorage.setItem` replaces a value in one step, so a write is whole;
//! setting aside copies the text to a free `onemorebrick/NAME.bad-N` first and only then
//! removes the old key, so a failure in between loses nothing.

use crate::shelf::{Entry, Shelf};

/// The prefix of every key the game uses.
const PREFIX: &str = "onemorebrick/";

/// A store of texts by key (the page's `localStorage`; a map in the tests).
pub trait KeyValue {
    /// The text under `key`, if any.
    ///
    /// # Errors
    /// The store's message when it cannot be read.
    fn get(&self, key: &str) -> Result<Option<String>, String>;
    /// Stores `value` under `key`, replacing the old value in one step.
    ///
    /// # Errors
    /// The store's message (full, turned off); the old value is then still there.
    fn set(&self, key: &str, value: &str) -> Result<(), String>;
    /// Removes `key`.
    ///
    /// # Errors
    /// The store's message.
    fn remove(&self, key: &str) -> Result<(), String>;
}

/// The page's `localStorage` (through `onemorebrick-web`).
#[cfg(target_arch = "wasm32")]
#[derive(Clone, Copy, Debug)]
pub struct LocalStorage;

#[cfg(target_arch = "wasm32")]
impl KeyValue for LocalStorage {
    fn get(&self, key: &str) -> Result<Option<String>, String> {
        onemorebrick_web::get(key)
    }
    fn set(&self, key: &str, value: &str) -> Result<(), String> {
        onemorebrick_web::set(key, value)
    }
    fn remove(&self, key: &str) -> Result<(), String> {
        onemorebrick_web::remove(key)
    }
}

/// The entries as keys of a [`KeyValue`] store.
#[derive(Clone, Debug)]
pub struct Keys<K> {
    store: K,
}

impl<K: KeyValue> Keys<K> {
    /// The entries in `store`.
    pub fn new(store: K) -> Self {
        Self { store }
    }

    /// The key of `entry`.
    pub fn key(entry: Entry) -> String {
        format!("{PREFIX}{}", entry.name())
    }
}

/// How messages name a key.
fn label_of(key: &str) -> String {
    format!("localStorage {key:?}")
}

impl<K: KeyValue> Shelf for Keys<K> {
    fn label(&self, entry: Entry) -> String {
        label_of(&Self::key(entry))
    }

    fn read(&self, entry: Entry) -> Result<Option<String>, String> {
        let key = Self::key(entry);
        self.store
            .get(&key)
            .map_err(|e| format!("{}: could not read: {e}", label_of(&key)))
    }

    fn write(&self, entry: Entry, text: &str) -> Result<(), String> {
        let key = Self::key(entry);
        self.store
            .set(&key, text)
            .map_err(|e| format!("{}: could not write: {e}", label_of(&key)))
    }

    fn set_aside(&self, entry: Entry) -> Result<String, String> {
        let key = Self::key(entry);
        let text = self.store.get(&key)?.unwrap_or_default();
        let mut free = None;
        for n in 1u32.. {
            let candidate = format!("{key}.bad-{n}");
            if self.store.get(&candidate)?.is_none() {
                free = Some(candidate);
                break;
            }
        }
        let target = free.expect("some suffix is free");
        self.store.set(&target, &text)?;
        self.store.remove(&key)?;
        Ok(label_of(&target))
    }
}

/// A map standing in for `localStorage` in the tests (shared by its clones, as the page's
/// storage is by every load of the page).
#[cfg(test)]
#[derive(Clone, Debug, Default)]
pub struct Memory {
    map: std::rc::Rc<std::cell::RefCell<std::collections::BTreeMap<String, String>>>,
}

#[cfg(test)]
impl Memory {
    /// Every key and its text.
    pub fn entries(&self) -> Vec<(String, String)> {
        self.map
            .borrow()
            .iter()
            .map(|(k, v)| (k.clone(), v.clone()))
            .collect()
    }
}

#[cfg(test)]
impl KeyValue for Memory {
    fn get(&self, key: &str) -> Result<Option<String>, String> {
        Ok(self.map.borrow().get(key).cloned())
    }
    fn set(&self, key: &str, value: &str) -> Result<(), String> {
        self.map
            .borrow_mut()
            .insert(key.to_owned(), value.to_owned());
        Ok(())
    }
    fn remove(&self, key: &str) -> Result<(), String> {
        self.map.borrow_mut().remove(key);
        Ok(())
    }
}
