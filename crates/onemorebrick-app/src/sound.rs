//! Sounds: short tones synthesised at start (no asset files), played on a hit, a broken
//! brick and the end of a round. They sound only when the crate is built with the `audio`
//! feature (macroquad's audio, which needs the system's sound library); without it
//! macroquad's audio calls do nothing.
//!
//! Without a sound device the game says once, in one line on standard error, that sound is
//! off and why, and goes on silently. Macroquad starts its sound library (quad-snd) with
//! every window, on a thread that panics when it cannot open a device, so two things guard
//! it: [`check_device`] looks for a device before the window opens (and sound stays off
//! without one: nothing is sent to the library's dead thread), and [`catch_library_failures`]
//! turns the library's panic into that one line instead of a backtrace, whenever it comes.

use std::path::Path;
use std::sync::atomic::{AtomicBool, Ordering};

use macroquad::audio::{PlaySoundParams, Sound, load_sound_from_bytes, play_sound};

/// Samples per second of the synthesised tones.
const RATE: u32 = 44_100;

/// Something worth a sound.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Cue {
    /// A ball hit a brick this frame.
    Hit,
    /// A brick broke this frame.
    Break,
    /// The round ended.
    RoundOver,
}

/// The cues of one frame: at most one of each, however many balls hit (a thousand hits in
/// a frame are one tick, not a roar).
pub fn cues(hits: u64, broken: usize, round_over: bool) -> Vec<Cue> {
    let mut out = Vec::new();
    if hits > 0 {
        out.push(Cue::Hit);
    }
    if broken > 0 {
        out.push(Cue::Break);
    }
    if round_over {
        out.push(Cue::RoundOver);
    }
    out
}

/// A mono 16-bit WAV file of a sine tone at `freq` Hz, `seconds` long, fading out.
pub fn tone_wav(freq: f32, seconds: f32, volume: f32) -> Vec<u8> {
    let samples = (seconds.max(0.0) * RATE as f32) as u32;
    let data_len = samples * 2;
    let mut wav = Vec::with_capacity(44 + data_len as usize);
    wav.extend_from_slice(b"RIFF");
    wav.extend_from_slice(&(36 + data_len).to_le_bytes());
    wav.extend_from_slice(b"WAVEfmt ");
    wav.extend_from_slice(&16u32.to_le_bytes());
    wav.extend_from_slice(&1u16.to_le_bytes()); // PCM
    wav.extend_from_slice(&1u16.to_le_bytes()); // mono
    wav.extend_from_slice(&RATE.to_le_bytes());
    wav.extend_from_slice(&(RATE * 2).to_le_bytes());
    wav.extend_from_slice(&2u16.to_le_bytes());
    wav.extend_from_slice(&16u16.to_le_bytes());
    wav.extend_from_slice(b"data");
    wav.extend_from_slice(&data_len.to_le_bytes());
    for i in 0..samples {
        let t = i as f32 / RATE as f32;
        let fade = 1.0 - i as f32 / samples as f32;
        let v = (t * freq * std::f32::consts::TAU).sin() * fade * fade * volume.clamp(0.0, 1.0);
        wav.extend_from_slice(&((v * f32::from(i16::MAX)) as i16).to_le_bytes());
    }
    wav
}

/// Whether sound is off for this run (no device, or the sound library failed).
static OFF: AtomicBool = AtomicBool::new(false);

/// Turns sound off, saying why once, in one line on standard error.
fn turn_off(why: &str) {
    if !OFF.swap(true, Ordering::SeqCst) {
        eprintln!("onemorebrick: sound is off: {why}");
    }
}

/// Replaces the panic message of the sound library's thread (and only that one) with the
/// one line of [`turn_off`]: every other panic still goes to the hook that was there. The
/// hook stays for the whole run, since the library's thread may also fail later (a device
/// unplugged). Call it first thing, before any window opens; it does nothing without the
/// `audio` feature.
pub fn catch_library_failures() {
    if !cfg!(feature = "audio") {
        return;
    }
    let previous = std::panic::take_hook();
    std::panic::set_hook(Box::new(move |info| {
        if info
            .location()
            .is_some_and(|l| from_sound_library(l.file()))
        {
            turn_off(&format!("the sound library failed: {}", panic_text(info)));
        } else {
            previous(info);
        }
    }));
}

/// Whether a panic at `file` is the sound library's.
fn from_sound_library(file: &str) -> bool {
    file.contains("quad-snd") || file.contains("quad_snd")
}

fn panic_text(info: &std::panic::PanicHookInfo<'_>) -> String {
    let payload = info.payload();
    payload
        .downcast_ref::<&str>()
        .map(|s| (*s).to_owned())
        .or_else(|| payload.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "no reason given".to_owned())
}

/// Before a window that plays sounds opens: with the `audio` feature, turns sound off (and
/// says why) if this machine has no sound device.
pub fn check_device() {
    if cfg!(feature = "audio") {
        if let Err(why) = probe(Path::new("/proc/asound/cards"), runtime_dir().as_deref()) {
            turn_off(&why);
        }
    }
}

fn runtime_dir() -> Option<std::path::PathBuf> {
    std::env::var_os("XDG_RUNTIME_DIR")
        .filter(|d| !d.is_empty())
        .map(Into::into)
}

/// Linux: a sound card listed in `cards` (`/proc/asound/cards`), a PulseAudio or PipeWire
/// server's socket in `runtime` (`$XDG_RUNTIME_DIR`), `$PULSE_SERVER`, or an ALSA
/// configuration of the user's or the system's (it may name any device) count as a device.
/// Elsewhere the platform's sound system always has one.
///
/// # Errors
/// Why there is none.
fn probe(cards: &Path, runtime: Option<&Path>) -> Result<(), String> {
    if !cfg!(target_os = "linux") {
        return Ok(());
    }
    let listed = std::fs::read_to_string(cards).is_ok_and(|text| lists_a_card(&text));
    let server = runtime
        .is_some_and(|r| serves(&r.join("pulse/native")) || serves(&r.join("pipewire-0")))
        || std::env::var_os("PULSE_SERVER").is_some();
    let configured = Path::new("/etc/asound.conf").exists()
        || std::env::var_os("HOME").is_some_and(|h| Path::new(&h).join(".asoundrc").exists());
    if listed || server || configured {
        Ok(())
    } else {
        Err("no sound device (no sound card, no PulseAudio or PipeWire server)".to_owned())
    }
}

/// Whether a sound server answers on the socket at `path`: a socket file that nobody serves
/// (a server that died, a session's leftovers) is no server. The sound library would try it,
/// its thread would fail at some moment while the game loads its sounds, and a sound sent
/// after that makes the library print "Audio thread died" on standard output (a race seen on
/// a busy CI machine).
fn serves(path: &Path) -> bool {
    #[cfg(unix)]
    {
        std::os::unix::net::UnixStream::connect(path).is_ok()
    }
    #[cfg(not(unix))]
    {
        path.exists()
    }
}

/// Whether `/proc/asound/cards` text lists a card: its lines start with the card's number
/// (" 0 [PCH  ]: ..."); without one it reads "--- no soundcards ---".
fn lists_a_card(text: &str) -> bool {
    text.lines()
        .any(|l| l.trim_start().starts_with(|c: char| c.is_ascii_digit()))
}

/// The game's sounds.
pub struct Sounds {
    hit: Sound,
    brick: Sound,
    round: Sound,
}

impl Sounds {
    /// Synthesises and loads the sounds; `None` if sound is off or the audio backend
    /// refuses one.
    pub async fn load() -> Option<Self> {
        if OFF.load(Ordering::SeqCst) {
            return None;
        }
        Some(Self {
            hit: load_sound_from_bytes(&tone_wav(880.0, 0.04, 0.25))
                .await
                .ok()?,
            brick: load_sound_from_bytes(&tone_wav(523.0, 0.12, 0.4))
                .await
                .ok()?,
            round: load_sound_from_bytes(&tone_wav(330.0, 0.25, 0.35))
                .await
                .ok()?,
        })
    }

    /// Plays the sound of `cue` (nothing once sound is off).
    pub fn play(&self, cue: Cue) {
        if OFF.load(Ordering::SeqCst) {
            return;
        }
        let sound = match cue {
            Cue::Hit => &self.hit,
            Cue::Break => &self.brick,
            Cue::RoundOver => &self.round,
        };
        play_sound(
            sound,
            PlaySoundParams {
                looped: false,
                volume: 1.0,
            },
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn u32_at(b: &[u8], i: usize) -> u32 {
        u32::from_le_bytes([b[i], b[i + 1], b[i + 2], b[i + 3]])
    }

    #[test]
    fn a_tone_is_a_valid_wav_of_the_right_length() {
        let wav = tone_wav(440.0, 0.1, 0.5);
        assert_eq!(&wav[..4], b"RIFF");
        assert_eq!(&wav[8..16], b"WAVEfmt ");
        assert_eq!(u32_at(&wav, 24), RATE);
        let data = u32_at(&wav, 40) as usize;
        assert_eq!(data, 4410 * 2);
        assert_eq!(wav.len(), 44 + data);
        assert_eq!(u32_at(&wav, 4) as usize, wav.len() - 8);
    }

    #[test]
    fn a_tone_is_audible_then_fades_out() {
        let wav = tone_wav(440.0, 0.1, 0.5);
        let samples: Vec<i16> = wav[44..]
            .chunks_exact(2)
            .map(|c| i16::from_le_bytes([c[0], c[1]]))
            .collect();
        let peak = |s: &[i16]| s.iter().map(|v| v.unsigned_abs()).max().unwrap();
        let n = samples.len();
        assert!(peak(&samples[..n / 4]) > 8000);
        assert!(peak(&samples[n * 9 / 10..]) < peak(&samples[..n / 4]) / 20);
    }

    #[test]
    fn the_card_list_tells_whether_there_is_a_card() {
        assert!(!lists_a_card("--- no soundcards ---\n"));
        assert!(!lists_a_card(""));
        let one = " 0 [PCH            ]: HDA-Intel - HDA Intel PCH\n                      HDA Intel PCH at 0xf7f10000 irq 32\n";
        assert!(lists_a_card(one));
    }

    #[test]
    fn the_probe_finds_a_card_or_a_sound_server() {
        let dir = std::env::temp_dir().join(format!("omb-probe-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(dir.join("run/pulse")).unwrap();
        let cards = dir.join("cards");
        std::fs::write(&cards, " 1 [USB   ]: USB-Audio - Headset\n").unwrap();
        assert!(probe(&cards, None).is_ok());
        let empty = dir.join("none");
        std::fs::write(&empty, "--- no soundcards ---\n").unwrap();
        // A socket file that nobody serves is no server; one that a server listens on is.
        std::fs::write(dir.join("run/pulse/native"), "").unwrap();
        let dead = probe(&empty, Some(&dir.join("run")));
        std::fs::remove_file(dir.join("run/pulse/native")).unwrap();
        let listener =
            std::os::unix::net::UnixListener::bind(dir.join("run/pulse/native")).unwrap();
        assert!(probe(&empty, Some(&dir.join("run"))).is_ok(), "a server");
        drop(listener);
        let quiet = probe(&empty, Some(&dir))
            .and(probe(&dir.join("absent"), None))
            .and(dead);
        let configured = Path::new("/etc/asound.conf").exists()
            || std::env::var_os("PULSE_SERVER").is_some()
            || std::env::var_os("HOME").is_some_and(|h| Path::new(&h).join(".asoundrc").exists());
        if cfg!(target_os = "linux") && !configured {
            let why = quiet.unwrap_err();
            assert!(why.contains("no sound device"), "{why}");
        }
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn only_the_sound_library_panics_are_caught() {
        let at = "/home/u/.cargo/registry/src/index.crates.io-0/quad-snd-0.2.8/src/alsa_snd.rs";
        assert!(from_sound_library(at));
        assert!(!from_sound_library("crates/onemorebrick-app/src/app.rs"));
        assert!(!from_sound_library("/rustc/abc/library/core/src/option.rs"));
    }

    #[test]
    fn a_busy_frame_is_one_sound_of_each_kind() {
        assert_eq!(cues(1000, 3, true), [Cue::Hit, Cue::Break, Cue::RoundOver]);
        assert!(cues(0, 0, false).is_empty());
        assert_eq!(cues(0, 1, false), [Cue::Break]);
    }
}
