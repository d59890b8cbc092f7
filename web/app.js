// The page: three rooms over one library (pendulum.js → pendulum.wasm).
// Every figure shown carries its JSON key and its value at full precision
// (data-key, data-value); the text beside it is rounded for reading.
import { load, call, listen, clearestChannel, PendulumError } from "./pendulum.js";
import { setUpLab } from "./lab.js";

const $ = (selector, root = document) => root.querySelector(selector);
const $$ = (selector, root = document) => [...root.querySelectorAll(selector)];

// ---- Numbers and their names ------------------------------------------

/** `value` to `digits` significant digits, as the command line rounds. */
export function fmt(value, digits = 6) {
  if (value === null || value === undefined) return "—";
  if (typeof value !== "number") return String(value);
  if (value === 0) return "0";
  const text = Number(value.toPrecision(digits)).toString();
  return text.includes("e") ? value.toPrecision(digits) : text;
}

const UNITS = [
  ["_rad_per_s", "rad/s"], ["_per_rad_s", "1/(rad·s)"], ["_per_rad", "1/rad"], ["_per_s", "1/s"],
  ["_s_per_day", "s/day"], ["_m_s2", "m/s²"], ["_rad_s", "rad/s"], ["_deg", "°"],
  ["_rad", "rad"], ["_ms", "ms"], ["_m", "m"], ["_s", "s"], ["_hz", "Hz"],
  ["_kg", "kg"], ["_j", "J"], ["_w", "W"], ["_db", "dB"], ["_ppm", "ppm"],
];
const NAMES = {
  period_s: "Period", small_angle_period_s: "Small-angle period",
  circular_error_s_per_day: "Circular error", beats_per_hour: "Beats per hour",
  g_m_s2: "g", length_m: "Length", shift_m: "Move of the bob", nut_turns: "Turns of the nut",
  equivalent_length_m: "Pendulum length", damped_period_s: "Damped period",
  q_factor: "Q", decay_time_s: "Decay time (amplitude to 1/e)",
  amplitude_half_life_s: "Amplitude half-life",
  amplitude_loss_per_period_rad: "Amplitude lost a period",
  omega_rad_s: "ω from the turning points", omega_n_rad_s: "ω₀, natural", zeta: "ζ, damping ratio",
  q_factor: "Q", amplitude0_rad: "Starting amplitude", amplitude_rad: "Amplitude",
  decay_rate_per_s: "Decay rate", offset_rad: "Zero offset", phase_rad: "Phase",
  small_angle_period_s: "Small-angle period", circular_error_coefficient: "Circular-error coefficient",
  residual_rms_s: "Residual rms",
};

/** A key's words and unit: `circular_error_s_per_day` → ["Circular error", "s/day"]. */
export function named(key) {
  const unit = UNITS.find(([suffix]) => key.endsWith(suffix));
  const bare = unit ? key.slice(0, -unit[0].length) : key;
  const words = NAMES[key] ?? bare.replaceAll("_", " ").replace(/^./, (c) => c.toUpperCase());
  return [words, unit ? unit[1] : ""];
}

/** Writes `value` into `el` with its key and full value as attributes. */
function show(el, key, value, digits = 6) {
  el.dataset.key = key;
  if (typeof value === "number") el.dataset.value = String(value);
  else delete el.dataset.value;
  el.textContent = fmt(value, digits);
}

// ---- Rooms ---------------------------------------------------------------

function route() {
  const room = (location.hash || "#timegrapher").slice(1);
  const known = $$(".room").map((r) => r.id);
  const here = known.includes(room) ? room : "timegrapher";
  for (const r of $$(".room")) r.hidden = r.id !== here;
  for (const a of $$("nav a")) a.classList.toggle("active", a.dataset.room === here);
}

// ---- Calculators ---------------------------------------------------------

/** A field's number (a decimal comma read as a point); refused in the
 * field's own words when it is not a finite number. */
function number(input) {
  const text = input.value.trim();
  const value = Number(text.replace(",", "."));
  if (!Number.isFinite(value)) {
    const label = input.closest("label")?.firstChild?.textContent.trim() ?? input.name;
    throw new PendulumError({ field: input.name, flag: null, message: `${label}: must be a finite number, got ${text}` });
  }
  return value;
}

function request(form) {
  const req = { command: form.dataset.command };
  for (const input of $$("input", form)) {
    if (input.value.trim() === "") continue;
    req[input.name] = number(input);
  }
  return req;
}

function calculate(form) {
  const dl = $("dl.result", form);
  dl.replaceChildren();
  let result;
  try {
    result = call(request(form));
  } catch (e) {
    const dd = document.createElement("dd");
    dd.className = "error";
    dd.textContent = e instanceof PendulumError ? e.message : String(e);
    dl.append(dd);
    return;
  }
  for (const key of dl.dataset.show.split(" ")) {
    if (!(key in result) || result[key] === null) continue;
    const [words, unit] = named(key);
    const dt = document.createElement("dt");
    dt.textContent = words;
    const dd = document.createElement("dd");
    const value = document.createElement("span");
    show(value, key, result[key], 7);
    dd.append(value, unit ? ` ${unit}` : "");
    dl.append(dt, dd);
  }
  if (form.dataset.command === "regulate") {
    const p = document.createElement("dd");
    p.className = "advice";
    const mm = Math.abs(result.shift_m) * 1000;
    const way = result.shift_m >= 0 ? "Lower" : "Raise";
    const turns = result.nut_turns == null ? "" : `: ${fmt(Math.abs(result.nut_turns), 3)} turn of the nut`;
    p.textContent = `${way} the bob ${fmt(mm, 3)} mm${turns}.`;
    dl.append(p);
  }
}

// ---- Timegrapher -----------------------------------------------------------

function options() {
  const form = $("#listen-form");
  const o = {};
  for (const name of ["bph", "lift_angle_deg", "every_s"]) {
    if (form.elements[name].value.trim() !== "") o[name] = number(form.elements[name]);
  }
  return o;
}

function error(message) {
  const box = $("#listen-error");
  box.hidden = !message;
  box.textContent = message ?? "";
}

/** Writes `value` with `decimals` after the point (and its sign). */
function fixed(el, key, value, decimals, sign = false) {
  show(el, key, value);
  if (typeof value === "number") el.textContent = (sign && value > 0 ? "+" : "") + value.toFixed(decimals);
}

function readouts(r, note) {
  const se = r.rate_se_s_per_day;
  fixed($("#out-rate"), "rate_s_per_day", r.rate_s_per_day ?? null, typeof se === "number" && se < 0.05 ? 2 : 1, true);
  fixed($("#out-beat-error"), "beat_error_ms", r.beat_error_ms ?? null, 2);
  const amplitude = typeof r.amplitude_deg === "number" ? r.amplitude_deg : null;
  show($("#out-amplitude"), "amplitude_deg", amplitude, 3);
  fixed($("#out-bph"), "beats_per_hour", r.beats_per_hour ?? null, 1);
  $("#listen-note").textContent = note ?? "";
}

function addWindow(w) {
  const table = $("#windows");
  table.hidden = false;
  const row = document.createElement("tr");
  const cells = [
    ["start_s", w.start_s, 6], ["end_s", w.end_s, 6], ["beats", w.beats, 7],
    ["rate_s_per_day", w.rate_s_per_day, 4], ["rate_se_s_per_day", w.rate_se_s_per_day, 2],
    ["beat_error_ms", w.beat_error_ms, 3], ["amplitude_deg", w.amplitude_deg, 3],
    ["snr_db", w.snr_db, 3],
  ];
  for (const [key, value, digits] of cells) {
    const td = document.createElement("td");
    show(td, key, value ?? null, digits);
    row.append(td);
  }
  $("tbody", table).append(row);
}

/** Sentences under a heading in `box` (nothing when there are none). */
function listed(box, title, items) {
  if (!items?.length) return;
  const h = document.createElement("h2");
  h.textContent = title;
  const ul = document.createElement("ul");
  for (const item of items) {
    const li = document.createElement("li");
    li.textContent = typeof item === "string" ? item : item.message;
    ul.append(li);
  }
  box.append(h, ul);
}

function words(w) {
  const box = $("#words");
  box.replaceChildren();
  listed(box, "Warnings", w?.warnings);
  listed(box, "What it shows", w?.findings);
  listed(box, "What to do", w?.advice);
}

/** Round steps for an axis over `span`: 1, 2 or 5 times a power of ten. */
function step(span, count) {
  const raw = span / count;
  const power = 10 ** Math.floor(Math.log10(raw));
  return [1, 2, 5, 10].map((m) => m * power).find((s) => s >= raw);
}

/** The paper strip: each tick's time against the nominal beat, ms. */
function strip(ticks, beat) {
  const canvas = $("#strip");
  const ratio = window.devicePixelRatio || 1;
  const width = canvas.clientWidth || 900;
  const height = width < 560 ? 210 : 260;
  canvas.width = Math.round(width * ratio);
  canvas.height = Math.round(height * ratio);
  canvas.style.height = `${height}px`;
  const ctx = canvas.getContext("2d");
  ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
  ctx.clearRect(0, 0, width, height);
  if (!ticks || ticks.time_s.length < 2 || !beat) return;
  const n = ticks.time_s.length;
  const t0 = ticks.time_s[0] - ticks.beat[0] * beat;
  // Early (a gaining clock) is up.
  const points = ticks.time_s.map((t, i) => [t, (t0 + ticks.beat[i] * beat - t) * 1e3, ticks.side[i]]);
  const ys = points.map((p) => p[1]).sort((a, b) => a - b);
  let lo = ys[Math.floor(0.005 * (n - 1))], hi = ys[Math.ceil(0.995 * (n - 1))];
  if (hi - lo < 0.2) { const mid = (hi + lo) / 2; lo = mid - 0.1; hi = mid + 0.1; }
  const dy = step(hi - lo, 4);
  lo = Math.floor(lo / dy) * dy; hi = Math.ceil(hi / dy) * dy;
  const tMin = points[0][0], tMax = points[n - 1][0];
  const dt = step(Math.max(tMax - tMin, 1e-3), width < 560 ? 3 : 6);
  const x0 = 52, x1 = width - 12, y0 = height - 26, y1 = 22;
  const X = (t) => x0 + ((t - tMin) / Math.max(tMax - tMin, 1e-9)) * (x1 - x0);
  const Y = (v) => y0 - ((v - lo) / (hi - lo)) * (y0 - y1);
  ctx.font = "12px system-ui, sans-serif";
  ctx.lineWidth = 1;
  ctx.textAlign = "right";
  for (let v = lo; v <= hi + dy / 2; v += dy) {
    ctx.strokeStyle = Math.abs(v) < dy / 2 ? "#b8b2a6" : "#e8e3d9";
    ctx.beginPath(); ctx.moveTo(x0, Y(v)); ctx.lineTo(x1, Y(v)); ctx.stroke();
    ctx.fillStyle = "#5b6472";
    ctx.fillText(fmt(Math.abs(v) < dy / 2 ? 0 : v, 4), x0 - 6, Y(v) + 4);
  }
  ctx.textAlign = "left";
  ctx.fillText("ms, early ↑", 4, 12);
  ctx.textAlign = "center";
  for (let t = Math.ceil((tMin) / dt) * dt; t <= tMax + 1e-9; t += dt) {
    ctx.fillText(`${fmt(t, 4)}`, X(t), height - 8);
  }
  ctx.textAlign = "right";
  ctx.fillText("s", x1, height - 8 - 14);
  const colours = ["#1f3a5f", "#c8962b"];
  const size = n > 5000 ? 1.5 : 2.5;
  for (const [t, v, side] of points) {
    ctx.fillStyle = colours[side ? 1 : 0];
    ctx.fillRect(X(t) - size / 2, Y(v) - size / 2, size, size);
  }
}

let lastStrip = null;
let lastTicks = null;

/** Offers `blob` as a download named `name`. */
function download(blob, name) {
  const a = document.createElement("a");
  a.href = URL.createObjectURL(blob);
  a.download = name;
  a.click();
  setTimeout(() => URL.revokeObjectURL(a.href), 10000);
}

/** The ticks as the command line's --ticks file writes them. */
export function ticksCsv(ticks) {
  const rows = ["time_s,side,sound_level,amplitude"];
  for (let i = 0; i < ticks.time_s.length; i++) {
    rows.push(`${ticks.time_s[i]},${ticks.side[i]},${ticks.sound_level[i]},${ticks.sound_level[i]}`);
  }
  return rows.join("\n") + "\n";
}

/** 16-bit mono WAV of Int16Array `parts` at `rate` Hz. */
export function wavBlob(parts, rate) {
  const bytes = parts.reduce((n, p) => n + p.byteLength, 0);
  const head = new DataView(new ArrayBuffer(44));
  const text = (at, s) => [...s].forEach((c, i) => head.setUint8(at + i, c.charCodeAt(0)));
  text(0, "RIFF"); head.setUint32(4, 36 + bytes, true); text(8, "WAVE");
  text(12, "fmt "); head.setUint32(16, 16, true); head.setUint16(20, 1, true); head.setUint16(22, 1, true);
  head.setUint32(24, rate, true); head.setUint32(28, rate * 2, true); head.setUint16(32, 2, true); head.setUint16(34, 16, true);
  text(36, "data"); head.setUint32(40, bytes, true);
  return new Blob([head, ...parts], { type: "audio/wav" });
}

function render(heard) {
  const r = heard.result;
  readouts(r, `${r.beats} beats over ${fmt(r.duration_s, 4)} s, ${r.missed} missed; signal to noise ${fmt(r.snr_db, 3)} dB.`);
  $("#windows tbody").replaceChildren();
  $("#windows").hidden = !(r.windows?.length);
  for (const w of r.windows ?? []) addWindow(w);
  words(heard.words);
  lastStrip = [heard.ticks, r.nominal_beat_s ?? r.mean_beat_s];
  lastTicks = heard.ticks;
  $("#save-ticks").disabled = !heard.ticks?.time_s.length;
  strip(...lastStrip);
  $("#whole-json").textContent = JSON.stringify(r, null, 2);
  document.body.dataset.heard = "1";
}

/** A WAV file's samples (PCM 8/16/24/32 or float 32/64), else null. */
export function readWav(buffer) {
  const v = new DataView(buffer);
  const tag = (at) => String.fromCharCode(...new Uint8Array(buffer, at, 4));
  if (buffer.byteLength < 12 || tag(0) !== "RIFF" || tag(8) !== "WAVE") return null;
  let at = 12, format = null, data = null;
  while (at + 8 <= buffer.byteLength) {
    const id = tag(at), size = v.getUint32(at + 4, true);
    if (id === "fmt ") {
      format = { code: v.getUint16(at + 8, true), channels: v.getUint16(at + 10, true), rate: v.getUint32(at + 12, true), bits: v.getUint16(at + 22, true) };
      // (WAVE_FORMAT_EXTENSIBLE: the format is its sub-format's.)
      if (format.code === 0xfffe && size >= 26) format.code = v.getUint16(at + 32, true);
    }
    if (id === "data") { data = { at: at + 8, size: Math.min(size, buffer.byteLength - at - 8) }; break; }
    at += 8 + size + (size % 2);
  }
  if (!format || !data) return null;
  const { code, channels, rate, bits } = format;
  if (![1, 3].includes(code) || ![8, 16, 24, 32, 64].includes(bits) || channels < 1) return null;
  const bytes = bits / 8, frames = Math.floor(data.size / (bytes * channels));
  const out = Array.from({ length: channels }, () => new Float32Array(frames));
  for (let i = 0; i < frames; i++) {
    for (let c = 0; c < channels; c++) {
      const p = data.at + (i * channels + c) * bytes;
      let x;
      if (code === 3) x = bits === 32 ? v.getFloat32(p, true) : v.getFloat64(p, true);
      else if (bits === 8) x = (v.getUint8(p) - 128) / 128;
      else if (bits === 16) x = v.getInt16(p, true) / 32768;
      else if (bits === 24) x = ((v.getInt8(p + 2) << 16) | (v.getUint8(p + 1) << 8) | v.getUint8(p)) / 8388608;
      else x = v.getInt32(p, true) / 2147483648;
      out[c][i] = x;
    }
  }
  return { rate, channels: out };
}

async function openRecording(file) {
  error(null);
  $("#listen-note").textContent = `Reading ${file.name}…`;
  const buffer = await file.arrayBuffer();
  let decoded = readWav(buffer);
  if (!decoded) {
    const ctx = new AudioContext();
    const audio = await ctx.decodeAudioData(buffer);
    decoded = { rate: audio.sampleRate, channels: Array.from({ length: audio.numberOfChannels }, (_, c) => audio.getChannelData(c)) };
    ctx.close();
  }
  $("#listen-note").textContent = `Listening to ${file.name}…`;
  await new Promise((r) => setTimeout(r, 20));
  try {
    // The channel whose ticks stand out clearest, as the command line's.
    const channel = clearestChannel(decoded.channels, decoded.rate);
    document.body.dataset.channel = String(channel + 1);
    const heard = listen(decoded.channels[channel], decoded.rate, options());
    render(heard);
    if (decoded.channels.length > 1) {
      $("#listen-note").textContent += ` Channel ${channel + 1} of ${decoded.channels.length} (its ticks stand out clearest).`;
    }
  } catch (e) {
    error(e instanceof PendulumError ? e.message : String(e));
    $("#listen-note").textContent = "";
  }
}

// The microphone: every sample to the listener once, in order. The
// reader only copies and posts; the listener works in a worker
// (listener-worker.js). A block the browser dropped (its timestamps jump)
// is filled with silence of its length, so that the ticks after it keep
// their times: the beats in it are missed, not misnumbered, and the gap
// is said with the result.
const mic = { stream: null, worker: null, stop: null, heard: 0, gaps: [], rate: 0, parts: [] };

function onWorker({ data }) {
  if (data.type === "pushed") {
    const { provisional, windows } = data.pushed;
    if (provisional) readouts(provisional, `First ${fmt(provisional.after_s, 3)} s (provisional, from ${provisional.beats} beats; each tick is timed finer as the listening goes on).`);
    for (const w of windows) {
      addWindow(w);
      const bph = $("#out-bph").dataset.value;
      readouts({ ...w, beats_per_hour: bph ? Number(bph) : null }, `Window ${fmt(w.start_s, 5)}–${fmt(w.end_s, 5)} s.`);
    }
  } else if (data.type === "finished") {
    const heard = data.heard;
    if (mic.gaps.length) {
      const [at, ms] = mic.gaps[0];
      const lost = mic.gaps.reduce((sum, g) => sum + g[1], 0);
      const others = data.others.map((p) => `from ${fmt(p.start_s, 4)} s, ${fmt(p.seconds, 3)} s long: ${p.rate_s_per_day === null ? "not read" : `${fmt(p.rate_s_per_day, 4)} s/day`}`);
      heard.words.warnings.unshift(`The browser lost sound ${mic.gaps.length} time(s) (about ${fmt(lost, 3)} ms by its clock; the first at ${fmt(at, 4)} s, ${fmt(ms, 3)} ms): the listening was cut there and each stretch read on its own. The figures are those of the longest stretch, from ${fmt(data.piece.start_s, 4)} s, ${fmt(data.piece.seconds, 3)} s long; the other stretches: ${others.join("; ")}.`);
    }
    render(heard);
  } else if (data.type === "error") {
    error(data.message);
    stopMic(false);
  }
}

async function startMic() {
  error(null);
  // (Refused before the microphone is asked for.)
  const opts = options();
  $("#windows tbody").replaceChildren();
  $("#windows").hidden = true;
  $("#words").replaceChildren();
  delete document.body.dataset.heard;
  const stream = await navigator.mediaDevices.getUserMedia({
    audio: { echoCancellation: false, noiseSuppression: false, autoGainControl: false, channelCount: 1 },
  });
  mic.stream = stream;
  mic.gaps = [];
  mic.parts = [];
  mic.heard = 0;
  $("#save-recording").disabled = true;
  const track = stream.getAudioTracks()[0];
  mic.worker?.terminate();
  mic.worker = new Worker("listener-worker.js", { type: "module" });
  mic.worker.onmessage = onWorker;
  $("#mic-start").disabled = true;
  $("#mic-stop").disabled = false;
  $("#listen-note").textContent = "Listening… the first reading comes within seconds for a watch, within a minute for a clock.";
  let started = false;
  const feed = (samples, sampleRate) => {
    if (!started) {
      mic.worker.postMessage({ type: "start", rate: sampleRate, options: opts });
      mic.rate = sampleRate;
      started = true;
    }
    mic.heard += samples.length / sampleRate;
    // (Kept at 16 bits for the recording's file: an hour at 48 kHz is
    // 345 MB.)
    mic.parts.push(Int16Array.from(samples, (x) => Math.max(-32768, Math.min(32767, Math.round(x * 32768)))));
    // (What was fed, for a reader of the page: seconds, and gaps cut.)
    document.body.dataset.micS = mic.heard.toFixed(3);
    document.body.dataset.micGaps = String(mic.gaps.length);
    mic.worker.postMessage({ type: "push", samples }, [samples.buffer]);
  };
  if ("MediaStreamTrackProcessor" in window) {
    const reader = new MediaStreamTrackProcessor({ track, maxBufferSize: 200 }).readable.getReader();
    let next = null;
    mic.stop = () => reader.cancel();
    (async () => {
      for (;;) {
        const { value: frame, done } = await reader.read();
        if (done) break;
        const n = frame.numberOfFrames, sr = frame.sampleRate;
        // (Timestamps are µs; a jump of more than a millisecond is a gap.)
        // The samples either side have no known time between them: the
        // listener cuts there and starts again (listener-worker.js).
        if (next !== null && frame.timestamp - next > 1000) {
          mic.gaps.push([mic.heard, (frame.timestamp - next) / 1e3]);
          mic.worker.postMessage({ type: "gap" });
        }
        next = frame.timestamp + (n / sr) * 1e6;
        const samples = new Float32Array(n);
        frame.copyTo(samples, { planeIndex: 0, format: "f32-planar" });
        frame.close();
        feed(samples, sr);
      }
    })();
  } else {
    const ctx = new AudioContext();
    await ctx.audioWorklet.addModule("capture-worklet.js");
    const source = ctx.createMediaStreamSource(stream);
    const node = new AudioWorkletNode(ctx, "capture");
    node.port.onmessage = (m) => feed(m.data, ctx.sampleRate);
    source.connect(node);
    mic.stop = () => ctx.close();
  }
}

function stopMic(finish = true) {
  mic.stop?.();
  mic.stop = null;
  mic.stream?.getTracks().forEach((t) => t.stop());
  mic.stream = null;
  $("#mic-start").disabled = false;
  $("#mic-stop").disabled = true;
  if (finish && mic.worker) mic.worker.postMessage({ type: "finish" });
  $("#save-recording").disabled = mic.parts.length === 0;
}

// ---- Start -----------------------------------------------------------------

async function main() {
  window.addEventListener("hashchange", route);
  window.addEventListener("resize", () => { if (lastStrip) strip(...lastStrip); });
  route();
  try {
    await load();
  } catch (e) {
    $("#status").textContent = `could not load the library: ${e}`;
    return;
  }
  $("#status").textContent = navigator.onLine ? "ready" : "ready (offline)";
  for (const form of $$("form.calc")) {
    form.addEventListener("input", () => calculate(form));
    form.addEventListener("submit", (e) => e.preventDefault());
    calculate(form);
  }
  setUpLab({ number, named, show, download, listed });
  // (For the bench: the calculators' first answers are on the page.)
  performance.mark("first-answer");
  $("#listen-file").addEventListener("change", (e) => {
    const file = e.target.files[0];
    if (file) openRecording(file).catch((err) => error(String(err)));
  });
  $("#mic-start").addEventListener("click", () => startMic().catch((err) => error(`The microphone: ${err.message ?? err}`)));
  $("#mic-stop").addEventListener("click", () => stopMic());
  $("#save-ticks").addEventListener("click", () => download(new Blob([ticksCsv(lastTicks)], { type: "text/csv" }), "ticks.csv"));
  $("#save-recording").addEventListener("click", () => download(wavBlob(mic.parts, mic.rate), "recording.wav"));
  if ("serviceWorker" in navigator && location.protocol !== "file:") {
    navigator.serviceWorker.register("sw.js").catch(() => {});
  }
  document.body.dataset.ready = "1";
}

main();
