//! Sounds: short tones synthesised at start (no asset files), played on a hit, a broken
//! brick and the end of a round. They sound only when the crate is built with the `audio`
//! feature (macroquad's audio, which needs the system's sound library); without it
//! macroquad's audio calls do nothing.

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

/// The game's sounds.
pub struct Sounds {
    hit: Sound,
    brick: Sound,
    round: Sound,
}

impl Sounds {
    /// Synthesises and loads the sounds; `None` if the audio backend refuses one.
    pub async fn load() -> Option<Self> {
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

    /// Plays the sound of `cue`.
    pub fn play(&self, cue: Cue) {
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
    fn a_busy_frame_is_one_sound_of_each_kind() {
        assert_eq!(cues(1000, 3, true), [Cue::Hit, Cue::Break, Cue::RoundOver]);
        assert!(cues(0, 0, false).is_empty());
        assert_eq!(cues(0, 1, false), [Cue::Break]);
    }
}
