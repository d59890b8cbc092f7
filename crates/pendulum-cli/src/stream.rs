//! Sound from standard input as it comes (`listen -`): a WAV stream, as
//! `arecord`, `sox -d -t wav -` or `ffmpeg -f wav -` write it (the
//! lengths its header gives are not read: a stream's writer cannot know
//! them), or raw samples (`--raw s16le`). Read on a
//! thread of its own in blocks of a tenth of a second, so that Ctrl-C is
//! seen even while the input is silent.

use crate::error::CliError;
use std::io::{BufReader, Read};
use std::sync::mpsc::{sync_channel, Receiver};

/// How raw samples are laid out.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Encoding {
    /// 16-bit signed integers, little-endian.
    S16le,
    /// 24-bit signed integers in three bytes, little-endian.
    S24le,
    /// 32-bit signed integers, little-endian.
    S32le,
    /// 32-bit floats, little-endian.
    F32le,
}

impl Encoding {
    /// `--raw`'s name of it.
    pub fn parse(name: &str) -> Result<Self, CliError> {
        match name {
            "s16le" => Ok(Self::S16le),
            "s24le" => Ok(Self::S24le),
            "s32le" => Ok(Self::S32le),
            "f32le" => Ok(Self::F32le),
            _ => Err(CliError::flag(
                "--raw",
                format!("must be s16le, s24le, s32le or f32le, got {name}"),
            )),
        }
    }

    fn bytes(self) -> usize {
        match self {
            Self::S16le => 2,
            Self::S24le => 3,
            Self::S32le | Self::F32le => 4,
        }
    }

    fn sample(self, b: &[u8]) -> f32 {
        match self {
            Self::S16le => f32::from(i16::from_le_bytes([b[0], b[1]])) / 32_768.0,
            Self::S24le => (i32::from_le_bytes([0, b[0], b[1], b[2]]) >> 8) as f32 / 8_388_608.0,
            Self::S32le => {
                (f64::from(i32::from_le_bytes([b[0], b[1], b[2], b[3]])) / 2_147_483_648.0) as f32
            }
            Self::F32le => f32::from_le_bytes([b[0], b[1], b[2], b[3]]),
        }
    }
}

/// What the stream is.
#[derive(Clone, Copy, Debug)]
pub struct Layout {
    /// Samples per second.
    pub sample_rate: u32,
    /// Channels, interleaved.
    pub channels: usize,
    /// How each sample is written.
    pub encoding: Encoding,
}

/// What standard input's bytes are: `raw` (the layout given), or a WAV
/// stream whose header comes first.
pub enum Given {
    /// Raw samples.
    Raw(Layout),
    /// A WAV stream.
    Wav,
}

/// A block of one channel's samples, or the reason reading stopped.
pub enum Block {
    /// Samples.
    Samples(Vec<f32>),
    /// The input could not be read.
    Failed(String),
}

/// The most channels a stream may interleave: as many as a WAV header can
/// count (16 bits).
pub const MAX_CHANNELS: usize = u16::MAX as usize;

/// The most bytes read as one block (a tenth of a second of 48 kHz stereo
/// is 38 kB; a block of a stream of many channels or a high rate holds
/// fewer frames).
const MAX_BLOCK_BYTES: usize = 1 << 20;

/// The frames read as one block: a tenth of a second, at least one frame,
/// at most [`MAX_BLOCK_BYTES`] (a whole frame always fits: it is at most
/// [`MAX_CHANNELS`] × 4 bytes).
fn block_frames(layout: &Layout) -> usize {
    let frame = layout.channels * layout.encoding.bytes();
    (layout.sample_rate as usize / 10).clamp(1, (MAX_BLOCK_BYTES / frame).max(1))
}

/// Opens `input` (standard input): its layout, and a receiver of blocks
/// of `channel` (from 0) read on a thread; the receiver's end is the end
/// of the input. Raw samples of more than [`MAX_CHANNELS`] channels are
/// refused by `--channels`.
pub fn open(
    input: impl Read + Send + 'static,
    given: Given,
    channel: usize,
) -> Result<(Layout, Receiver<Block>), CliError> {
    let mut reader = BufReader::with_capacity(1 << 16, input);
    let layout = match given {
        Given::Raw(layout) => {
            if !(1..=MAX_CHANNELS).contains(&layout.channels) {
                return Err(CliError::flag(
                    "--channels",
                    format!(
                        "must be 1 to {MAX_CHANNELS} (the most a WAV stream can hold), got {}",
                        layout.channels
                    ),
                ));
            }
            layout
        }
        Given::Wav => wav_header(&mut reader)?,
    };
    if channel >= layout.channels {
        return Err(CliError::flag(
            "--channel",
            format!(
                "the input has {} channel(s); give 1 to {}",
                layout.channels, layout.channels
            ),
        ));
    }
    let (send, receive) = sync_channel(64);
    let frame = layout.channels * layout.encoding.bytes();
    let frames = block_frames(&layout);
    std::thread::spawn(move || {
        let mut bytes = vec![0u8; frame * frames];
        let mut filled = 0;
        loop {
            let n = match reader.read(&mut bytes[filled..]) {
                Ok(n) => n,
                Err(e) if e.kind() == std::io::ErrorKind::Interrupted => continue,
                Err(e) => {
                    let _ = send.send(Block::Failed(format!("standard input: {e}")));
                    return;
                }
            };
            filled += n;
            let whole = filled / frame * frame;
            if (n == 0 || whole == bytes.len()) && whole > 0 {
                let at = channel * layout.encoding.bytes();
                let samples: Vec<f32> = bytes[..whole]
                    .chunks_exact(frame)
                    .map(|f| layout.encoding.sample(&f[at..]))
                    .collect();
                if send.send(Block::Samples(samples)).is_err() {
                    return;
                }
                bytes.copy_within(whole..filled, 0);
                filled -= whole;
            }
            if n == 0 {
                // (A last partial frame is dropped: the writer stopped mid-frame.)
                return;
            }
        }
    });
    Ok((layout, receive))
}

/// A WAV stream's header (RIFF chunks up to `data`); the reader is left
/// at the first sample. Read here, not by hound: hound refuses the
/// lengths a stream's writer puts in (`arecord` 0x7fffffff, `ffmpeg`
/// 0xffffffff: no whole number of samples), which a stream ignores anyway.
fn wav_header<R: Read>(reader: &mut R) -> Result<Layout, CliError> {
    let bad = |what: &str| {
        CliError::other(format!(
            "standard input: not a WAV stream ({what}); for raw samples give --raw and \
             --sample-rate"
        ))
    };
    let mut take = |n: usize| -> Result<Vec<u8>, CliError> {
        let mut b = vec![0u8; n];
        reader
            .read_exact(&mut b)
            .map_err(|_| bad("it ends within its header"))?;
        Ok(b)
    };
    let riff = take(12)?;
    if &riff[..4] != b"RIFF" || &riff[8..12] != b"WAVE" {
        return Err(bad("no RIFF WAVE header"));
    }
    let mut format: Option<(u16, usize, u32, u16)> = None;
    loop {
        let head = take(8)?;
        let len = u32::from_le_bytes([head[4], head[5], head[6], head[7]]) as usize;
        match &head[..4] {
            b"fmt " => {
                if !(16..=1024).contains(&len) {
                    return Err(bad("a fmt chunk of the wrong length"));
                }
                let f = take(len + len % 2)?;
                let u16_at = |i: usize| u16::from_le_bytes([f[i], f[i + 1]]);
                let mut tag = u16_at(0);
                // WAVE_FORMAT_EXTENSIBLE: the format is the sub-format's.
                if tag == 0xFFFE && len >= 26 {
                    tag = u16_at(24);
                }
                let rate = u32::from_le_bytes([f[4], f[5], f[6], f[7]]);
                format = Some((tag, usize::from(u16_at(2)), rate, u16_at(14)));
            }
            b"data" => break,
            _ => {
                // (Chunks before the samples: LIST, fact, PEAK.)
                if len > 1 << 20 {
                    return Err(bad("a chunk before the samples longer than 1 MiB"));
                }
                take(len + len % 2)?;
            }
        }
    }
    let (tag, channels, sample_rate, bits) = format.ok_or_else(|| bad("no fmt chunk"))?;
    let encoding = match (tag, bits) {
        (1, 16) => Encoding::S16le,
        (1, 24) => Encoding::S24le,
        (1, 32) => Encoding::S32le,
        (3, 32) => Encoding::F32le,
        _ => {
            return Err(CliError::other(format!(
                "standard input: WAV format {tag} with {bits}-bit samples is not read; send \
                 16, 24 or 32-bit integers or 32-bit floats"
            )))
        }
    };
    if channels == 0 || sample_rate == 0 {
        return Err(bad("no channels or no sample rate"));
    }
    Ok(Layout {
        sample_rate,
        channels,
        encoding,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A tenth of a second a block, within a mebibyte, never no frame.
    #[test]
    fn blocks_are_a_tenth_of_a_second_within_a_mebibyte() {
        let layout = |sample_rate, channels, encoding| Layout {
            sample_rate,
            channels,
            encoding,
        };
        assert_eq!(block_frames(&layout(48_000, 2, Encoding::S16le)), 4800);
        assert_eq!(block_frames(&layout(5, 1, Encoding::S16le)), 1);
        let widest = layout(u32::MAX, MAX_CHANNELS, Encoding::F32le);
        let frames = block_frames(&widest);
        assert_eq!(frames, 4);
        assert!(frames * MAX_CHANNELS * 4 <= MAX_BLOCK_BYTES);
        assert_eq!(block_frames(&layout(u32::MAX, 1, Encoding::S16le)), 1 << 19);
    }
}
