//! A shelf: where the saves' texts live, by entry. `storage` keeps the promises (what is
//! checked, what is never overwritten); a shelf only reads, writes whole and sets aside.

/// One of the texts the game keeps.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Entry {
    /// The saved game (`onemorebrick::save`'s JSON).
    Game,
    /// The best score ever (a decimal number and a newline).
    Best,
    /// The settings (`key = value` lines).
    Settings,
}

impl Entry {
    /// The entry's name: its file name on the desktop, the end of its key in the browser.
    pub fn name(self) -> &'static str {
        match self {
            Entry::Game => "game.json",
            Entry::Best => "best-score.txt",
            Entry::Settings => "settings.txt",
        }
    }
}

/// Where the entries are kept. Every message an implementation returns names the entry.
pub trait Shelf {
    /// How messages name `entry` (its path, its key).
    fn label(&self, entry: Entry) -> String;

    /// The text of `entry`, or `None` if there is none.
    ///
    /// # Errors
    /// A message naming the entry when it exists but cannot be read.
    fn read(&self, entry: Entry) -> Result<Option<String>, String>;

    /// Replaces `entry` with `text`, whole: a failure at any point leaves the old text or
    /// the new one, never a mix.
    ///
    /// # Errors
    /// A message naming the entry (the old text is then still there).
    fn write(&self, entry: Entry, text: &str) -> Result<(), String>;

    /// Moves `entry`'s text out of the way, to a name of its own not used before (`NAME.bad-N`
    /// with the smallest free `N` from 1), and says where it went (as [`Shelf::label`] does).
    ///
    /// # Errors
    /// A message if it could not be moved (it is then still where it was).
    fn set_aside(&self, entry: Entry) -> Result<String, String>;
}
