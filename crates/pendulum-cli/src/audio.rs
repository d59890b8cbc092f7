//! Sound files: decoding any recording with symphonia (WAV, FLAC, Ogg
//! Vorbis, MP3, AAC in MP4/M4A), streamed in blocks of one channel, and
//! writing a 16-bit WAV as a stream.

use crate::error::CliError;
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
    let extent = match seconds {
        Some(s) => Extent::Frames((s * f64::from(header.sample_rate)).ceil() as u64),
        None => Extent::Whole,
    };
    let mut mono: Vec<f32> = Vec::new();
    decode_frames(path, extent, |frames, count| {
        mono.clear();
        mono.extend(frames.iter().skip(channel).step_by(count));
        each(&mono);
    })
}

/// Decodes `extent` of `path`, giving `each` interleaved frames and the
/// number of channels.
fn decode_frames(
    path: &Path,
    extent: Extent,
    mut each: impl FnMut(&[f32], usize),
) -> Result<Info, CliError> {
    let file_name = path.display().to_string();
    let fail = |what: String| CliError::other(format!("{file_name}: {what}"));
    let file = std::fs::File::open(path).map_err(|e| fail(format!("cannot read it: {e}")))?;
    let stream = MediaSourceStream::new(Box::new(file), Default::default());
    let mut hint = Hint::new();
    if let Some(ext) = path.extension().and_then(|e| e.to_str()) {
        hint.with_extension(ext);
    }
    let probed = symphonia::default::get_probe()
        .format(
            &hint,
            stream,
            &FormatOptions::default(),
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
        .ok_or_else(|| fail("its sample rate is not stated".into()))?;
    let channels = track.codec_params.channels.map_or(1, |c| c.count());
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
    Ok(info)
}

/// The louder channel of `path` over its first ten seconds (0-based),
/// from one decoding of those seconds.
pub fn louder_channel(path: &Path) -> Result<usize, CliError> {
    let header = info(path)?;
    if header.channels < 2 {
        return Ok(0);
    }
    let mut energy = vec![0.0_f64; header.channels];
    let ten_seconds = 10 * u64::from(header.sample_rate);
    decode_frames(path, Extent::Frames(ten_seconds), |frames, count| {
        for frame in frames.chunks_exact(count) {
            for (e, &x) in energy.iter_mut().zip(frame) {
                *e += f64::from(x) * f64::from(x);
            }
        }
    })?;
    Ok(energy
        .iter()
        .enumerate()
        .max_by(|a, b| a.1.total_cmp(b.1))
        .map_or(0, |(i, _)| i))
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
