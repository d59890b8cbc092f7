//! Sound files: decoding any recording with symphonia (WAV, FLAC, Ogg
//! Vorbis, MP3, AAC in MP4/M4A), streamed in blocks of one channel, and
//! writing a 16-bit WAV as a stream.

use crate::error::CliError;
use std::cell::Cell;
use std::io::Read;
use std::path::Path;
use symphonia::core::audio::SampleBuffer;
use symphonia::core::codecs::{DecoderOptions, CODEC_TYPE_NULL};
use symphonia::core::errors::Error as AudioError;
use symphonia::core::formats::FormatOptions;
use symphonia::core::io::MediaSourceStream;
use symphonia::core::meta::MetadataOptions;
use symphonia::core::probe::Hint;

/// What a recording is.
#[derive(Clone, Copy, Debug)]
pub struct Info {
    /// Samples per second.
    pub sample_rate: u32,
    /// Channels.
    pub channels: usize,
}

/// How much of a file to decode.
enum Extent {
    /// The header only.
    Header,
    /// The first frames (samples per channel).
    Frames(u64),
    /// All of it.
    Whole,
}

/// What `path` is (sample rate and channels), from its header alone.
pub fn info(path: &Path) -> Result<Info, CliError> {
    decode_frames(path, Extent::Header, |_, _| {})
}

/// Decodes `path`, giving `each` the samples of `channel` (0-based) in
/// blocks: all of them, or about the first `seconds` (whole packets).
/// Returns what the recording is.
pub fn decode(
    path: &Path,
    channel: usize,
    seconds: Option<f64>,
    mut each: impl FnMut(&[f32]),
) -> Result<Info, CliError> {
    let header = info(path)?;
    if channel >= header.channels {
        return Err(CliError::flag(
            "--channel",
            format!(
                "{} has {} channel(s); give 1 to {}",
                path.display(),
                header.channels,
                header.channels
            ),
        ));
    }
    // The encoder's priming samples of an MP4 (AAC) file, which symphonia
    // 0.5 reads from the edit list but does not trim.
    let mut skip = mp4_priming(path).map_or(0, |(time, scale)| {
        (time as f64 * f64::from(header.sample_rate) / f64::from(scale)).round() as u64
    });
    // The first `seconds` of the recording itself: the priming is decoded
    // and dropped on top of them (a first pass cut short by it would take
    // a long recording for one that ends within the pass).
    let extent = match seconds {
        Some(s) => Extent::Frames((s * f64::from(header.sample_rate)).ceil() as u64 + skip),
        None => Extent::Whole,
    };
    let mut mono: Vec<f32> = Vec::new();
    decode_frames(path, extent, |frames, count| {
        mono.clear();
        // A float file's NaN or infinite sample is damage: heard as silence.
        mono.extend(frames.iter().skip(channel).step_by(count).map(|&x| {
            if x.is_finite() {
                x
            } else {
                0.0
            }
        }));
        let drop = skip.min(mono.len() as u64) as usize;
        skip -= drop as u64;
        if drop < mono.len() {
            each(&mono[drop..]);
        }
    })
}

thread_local! {
    /// Set while the decoder runs: a panic inside it is a damaged file,
    /// reported as such, not a defect of ours.
    static DECODING: Cell<bool> = const { Cell::new(false) };
}

/// Whether a panic now is the decoder's on a damaged file (so the panic
/// hook stays quiet and [`decode_frames`] reports it in one line).
pub fn quiet_panics() -> bool {
    DECODING.with(Cell::get)
}

/// The sound formats we decode, by their first bytes: RIFF/WAVE (and
/// RF64), FLAC, Ogg, MP3 (an ID3 tag or an MPEG frame sync, which ADTS
/// AAC shares) and MP4/M4A (an `ftyp` box). Anything else is refused at
/// once, before the decoder would search the whole file for a frame.
fn known_sound_format(head: &[u8]) -> bool {
    let at = |offset: usize, magic: &[u8]| head.get(offset..offset + magic.len()) == Some(magic);
    (at(0, b"RIFF") || at(0, b"RF64")) && at(8, b"WAVE")
        || at(0, b"fLaC")
        || at(0, b"OggS")
        || at(0, b"ID3")
        || at(4, b"ftyp")
        || (head.len() >= 2 && head[0] == 0xFF && head[1] & 0xE0 == 0xE0)
}

/// Decodes `extent` of `path`, giving `each` interleaved frames and the
/// number of channels. A decoder that fails on a damaged file (a panic
/// inside symphonia) is reported as a damaged file.
fn decode_frames(
    path: &Path,
    extent: Extent,
    mut each: impl FnMut(&[f32], usize),
) -> Result<Info, CliError> {
    let file_name = path.display().to_string();
    let fail = |what: String| CliError::other(format!("{file_name}: {what}"));
    let mut file =
        crate::file::open_input_file(path).map_err(|e| fail(format!("cannot read it: {e}")))?;
    let regular = file.metadata().is_ok_and(|m| m.is_file());
    if !regular {
        return Err(fail(
            "is not a regular file; give a sound file (WAV, FLAC, Ogg, MP3 or M4A)".into(),
        ));
    }
    let mut head = Vec::with_capacity(16);
    (&mut file)
        .take(16)
        .read_to_end(&mut head)
        .map_err(|e| fail(format!("cannot read it: {e}")))?;
    if !known_sound_format(&head) {
        return Err(fail(
            "not a sound file: its first bytes are none of WAV, FLAC, Ogg, MP3 or M4A".into(),
        ));
    }
    drop(file);
    let file =
        crate::file::open_input_file(path).map_err(|e| fail(format!("cannot read it: {e}")))?;
    DECODING.with(|d| d.set(true));
    let result = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
        decode_file(file, path, extent, &mut each, &fail)
    }));
    DECODING.with(|d| d.set(false));
    result.unwrap_or_else(|_| {
        Err(fail(
            "the decoder failed on it: the file is damaged or its header is not valid".into(),
        ))
    })
}

fn decode_file(
    file: std::fs::File,
    path: &Path,
    extent: Extent,
    each: &mut impl FnMut(&[f32], usize),
    fail: &impl Fn(String) -> CliError,
) -> Result<Info, CliError> {
    let stream = MediaSourceStream::new(Box::new(file), Default::default());
    let mut hint = Hint::new();
    if let Some(ext) = path.extension().and_then(|e| e.to_str()) {
        hint.with_extension(ext);
    }
    let probed = symphonia::default::get_probe()
        .format(
            &hint,
            stream,
            &FormatOptions {
                // Trim the encoder's delay and padding (MP3 LAME/Xing headers, MP4
                // edit lists) so that times are the recording's own.
                enable_gapless: true,
                ..Default::default()
            },
            &MetadataOptions::default(),
        )
        .map_err(|e| fail(format!("not a sound file symphonia can read ({e})")))?;
    let mut format = probed.format;
    let track = format
        .tracks()
        .iter()
        .find(|t| t.codec_params.codec != CODEC_TYPE_NULL)
        .ok_or_else(|| fail("no audio track in it".into()))?;
    let track_id = track.id;
    let sample_rate = track
        .codec_params
        .sample_rate
        .filter(|&r| r > 0)
        .ok_or_else(|| fail("its sample rate is not stated (or is 0) in its header".into()))?;
    let channels = track.codec_params.channels.map_or(1, |c| c.count());
    let stated = track.codec_params.n_frames;
    let info = Info {
        sample_rate,
        channels,
    };
    let limit = match extent {
        Extent::Header => return Ok(info),
        Extent::Frames(n) => n,
        Extent::Whole => u64::MAX,
    };
    let mut decoder = symphonia::default::get_codecs()
        .make(&track.codec_params, &DecoderOptions::default())
        .map_err(|e| fail(format!("its codec is not supported ({e})")))?;
    let mut buffer: Option<SampleBuffer<f32>> = None;
    let mut frames = 0_u64;
    while frames < limit {
        let packet = match format.next_packet() {
            Ok(p) => p,
            Err(AudioError::IoError(e)) if e.kind() == std::io::ErrorKind::UnexpectedEof => break,
            Err(AudioError::ResetRequired) => break,
            Err(e) => return Err(fail(format!("cannot be read to the end ({e})"))),
        };
        if packet.track_id() != track_id {
            continue;
        }
        let decoded = match decoder.decode(&packet) {
            Ok(d) => d,
            // A damaged packet is skipped, as players do.
            Err(AudioError::DecodeError(_)) => continue,
            Err(e) => return Err(fail(format!("cannot be decoded ({e})"))),
        };
        let spec = *decoded.spec();
        let needed = decoded.capacity() as u64;
        let buf = match &mut buffer {
            Some(b) if b.capacity() as u64 >= needed * spec.channels.count() as u64 => b,
            _ => buffer.insert(SampleBuffer::<f32>::new(needed, spec)),
        };
        buf.copy_interleaved_ref(decoded);
        let count = spec.channels.count().max(1);
        each(buf.samples(), count);
        frames += (buf.samples().len() / count) as u64;
    }
    // A file that ends well before the length its header states was cut
    // short (a copy or an upload that stopped): say so rather than analyse
    // a part of it as if it were all.
    if let (Extent::Whole, Some(stated)) = (extent, stated) {
        let slack = (0.1 * f64::from(sample_rate)).max(0.001 * stated as f64) as u64;
        if frames + slack < stated {
            let rate = f64::from(sample_rate);
            return Err(fail(format!(
                "ends after {:.1} s of the {:.1} s its header states: the file is truncated",
                frames as f64 / rate,
                stated as f64 / rate
            )));
        }
    }
    Ok(info)
}

/// The samples an MP4 file's audio track starts with before its content
/// (an AAC encoder's priming: 1,024 samples from ffmpeg, 2,112 from Apple's
/// encoders): the media time of the first edit of its edit list, in the
/// track's own timescale (ISO/IEC 14496-12, boxes `moov/trak/edts/elst`
/// and `moov/trak/mdia/mdhd`): `(media time, timescale)`. `None` for
/// other files, or an MP4 without an edit list.
fn mp4_priming(path: &Path) -> Option<(u64, u32)> {
    let mut head = [0_u8; 8];
    let mut file = std::fs::File::open(path).ok()?;
    file.read_exact(&mut head).ok()?;
    if &head[4..8] != b"ftyp" {
        return None;
    }
    // The moov box is small (kilobytes) but may sit after the media data:
    // read the file's boxes one by one, keeping only moov.
    let moov = {
        use std::io::{Seek, SeekFrom};
        let mut offset = 0_u64;
        loop {
            file.seek(SeekFrom::Start(offset)).ok()?;
            let mut h = [0_u8; 16];
            file.read_exact(&mut h[..8]).ok()?;
            let mut size = u64::from(u32::from_be_bytes(h[0..4].try_into().ok()?));
            if size == 1 {
                file.read_exact(&mut h[8..16]).ok()?;
                size = u64::from_be_bytes(h[8..16].try_into().ok()?);
            }
            if size < 8 {
                return None;
            }
            if &h[4..8] == b"moov" {
                if size > 64 << 20 {
                    return None;
                }
                file.seek(SeekFrom::Start(offset)).ok()?;
                let mut moov = vec![0_u8; usize::try_from(size).ok()?];
                file.read_exact(&mut moov).ok()?;
                break moov;
            }
            offset = offset.checked_add(size)?;
        }
    };
    // The boxes inside `data`: (type, contents).
    fn boxes(data: &[u8]) -> Vec<(&[u8], &[u8])> {
        let mut out = Vec::new();
        let mut at = 0_usize;
        while at + 8 <= data.len() {
            let size = u32::from_be_bytes([data[at], data[at + 1], data[at + 2], data[at + 3]]);
            let (size, header) = match size {
                0 => (data.len() - at, 8),
                1 if at + 16 <= data.len() => {
                    let big =
                        u64::from_be_bytes(data[at + 8..at + 16].try_into().unwrap_or([0; 8]));
                    (usize::try_from(big).unwrap_or(0), 16)
                }
                n => (n as usize, 8),
            };
            if size < header || at + size > data.len() {
                break;
            }
            out.push((&data[at + 4..at + 8], &data[at + header..at + size]));
            at += size;
        }
        out
    }
    let be32 = |b: &[u8], at: usize| -> Option<u32> {
        Some(u32::from_be_bytes(b.get(at..at + 4)?.try_into().ok()?))
    };
    let moov_boxes = boxes(&moov);
    let moov_body = moov_boxes.iter().find(|b| b.0 == b"moov")?.1;
    for (kind, trak) in boxes(moov_body) {
        if kind != b"trak" {
            continue;
        }
        let inner = boxes(trak);
        let Some(mdia) = inner.iter().find(|b| b.0 == b"mdia") else {
            continue;
        };
        let mdia = boxes(mdia.1);
        // Only the sound track.
        let is_sound = mdia
            .iter()
            .any(|b| b.0 == b"hdlr" && b.1.get(8..12) == Some(b"soun"));
        if !is_sound {
            continue;
        }
        let mdhd = mdia.iter().find(|b| b.0 == b"mdhd")?.1;
        let timescale = match mdhd.first()? {
            0 => be32(mdhd, 12)?,
            _ => be32(mdhd, 20)?,
        };
        let edts = inner.iter().find(|b| b.0 == b"edts")?.1;
        let elst = boxes(edts).into_iter().find(|b| b.0 == b"elst")?.1;
        let version = *elst.first()?;
        let entries = be32(elst, 4)? as usize;
        let width = if version == 1 { 20 } else { 12 };
        for e in 0..entries.min(16) {
            let at = 8 + e * width;
            let media_time = if version == 1 {
                i64::from_be_bytes(elst.get(at + 8..at + 16)?.try_into().ok()?)
            } else {
                i64::from(be32(elst, at + 4)? as i32)
            };
            // An empty edit (media time -1) delays the start; skip it.
            if media_time >= 0 {
                return (timescale > 0).then_some((media_time as u64, timescale));
            }
        }
        return None;
    }
    None
}

/// The channel of `path` (0-based) whose ticks stand out clearest over
/// its first thirty seconds, by the library's
/// [`pendulum_theory::listening::channels::clearest_channel`], from one
/// decoding of those seconds.
pub fn clearest_channel(path: &Path) -> Result<usize, CliError> {
    let header = info(path)?;
    if header.channels < 2 {
        return Ok(0);
    }
    let mut channels = vec![Vec::new(); header.channels];
    let thirty_seconds = 30 * u64::from(header.sample_rate);
    decode_frames(path, Extent::Frames(thirty_seconds), |frames, count| {
        for frame in frames.chunks_exact(count) {
            for (c, &x) in channels.iter_mut().zip(frame) {
                c.push(x);
            }
        }
    })?;
    Ok(pendulum_theory::listening::channels::clearest_channel(
        &channels,
        f64::from(header.sample_rate),
    ))
}

/// The 44-byte header of a 16-bit mono PCM WAV file of `samples` samples
/// at `sample_rate` (the canonical RIFF/WAVE layout: "RIFF" chunk, "fmt "
/// chunk of 16 bytes, "data" chunk). Written directly rather than with
/// hound, whose writer must seek back to fill in the lengths: the length
/// is known beforehand here, and the samples can then stream to a file or
/// to standard output. `None` if the data would pass the format's 4 GiB.
pub fn wav_header(samples: u64, sample_rate: u32) -> Option<[u8; 44]> {
    let data = u32::try_from(samples.checked_mul(2)?).ok()?;
    let riff = data.checked_add(36)?;
    let mut h = [0_u8; 44];
    h[0..4].copy_from_slice(b"RIFF");
    h[4..8].copy_from_slice(&riff.to_le_bytes());
    h[8..12].copy_from_slice(b"WAVE");
    h[12..16].copy_from_slice(b"fmt ");
    h[16..20].copy_from_slice(&16_u32.to_le_bytes());
    h[20..22].copy_from_slice(&1_u16.to_le_bytes()); // PCM
    h[22..24].copy_from_slice(&1_u16.to_le_bytes()); // mono
    h[24..28].copy_from_slice(&sample_rate.to_le_bytes());
    h[28..32].copy_from_slice(&(2 * sample_rate).to_le_bytes()); // bytes/s
    h[32..34].copy_from_slice(&2_u16.to_le_bytes()); // bytes per frame
    h[34..36].copy_from_slice(&16_u16.to_le_bytes()); // bits per sample
    h[36..40].copy_from_slice(b"data");
    h[40..44].copy_from_slice(&data.to_le_bytes());
    Some(h)
}

/// `samples` in [-1, 1] as 16-bit little-endian PCM, appended to `bytes`.
pub fn pcm16(samples: &[f32], bytes: &mut Vec<u8>) {
    for &x in samples {
        let v = (f64::from(x) * 32767.0).round().clamp(-32768.0, 32767.0) as i16;
        bytes.extend_from_slice(&v.to_le_bytes());
    }
}

/// One channel (0-based) of a sound file as the listening analysis's
/// source of sample blocks, decoded anew at each pass.
pub struct FileSource<'a> {
    /// The file.
    pub path: &'a Path,
    /// The channel, from 0.
    pub channel: usize,
    /// What the file is.
    pub info: Info,
}

impl pendulum_theory::listening::analysis::SampleSource for FileSource<'_> {
    type Error = CliError;

    fn sample_rate(&self) -> u32 {
        self.info.sample_rate
    }

    fn read(&mut self, seconds: Option<f64>, each: &mut dyn FnMut(&[f32])) -> Result<(), CliError> {
        decode(self.path, self.channel, seconds, each).map(|_| ())
    }
}
