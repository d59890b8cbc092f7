// The glue between the page and the library's WebAssembly exports
// (crates/pendulum-wasm): JSON requests in, the command line's --json
// keys out. A refusal comes back as a PendulumError carrying the command
// line's sentence and the field it is about.

export class PendulumError extends Error {
  constructor(error) {
    super(error.message);
    this.field = error.field;
    this.flag = error.flag;
  }
}

let wasm = null;
const encoder = new TextEncoder();
const decoder = new TextDecoder();

/** Loads the module once (from the page's own files: offline once cached). */
export async function load(url = new URL("pendulum.wasm", import.meta.url)) {
  if (wasm) return;
  const response = await fetch(url);
  const module = await WebAssembly.compile(await response.arrayBuffer());
  const instance = await WebAssembly.instantiate(module, unused(module));
  wasm = instance.exports;
}

/**
 * The module's imports, none of which the library calls: the workbook
 * reader's zip crate links getrandom's browser backend (for encrypted
 * archives, which a measurement workbook never is), and with it
 * wasm-bindgen's placeholders. Each is a function that throws, so a call
 * would be an error with its name, never a silent wrong answer.
 */
function unused(module) {
  const imports = {};
  for (const { module: from, name } of WebAssembly.Module.imports(module)) {
    imports[from] ??= {};
    imports[from][name] = () => {
      throw new Error(`pendulum.wasm called ${from}.${name}, which the page does not provide`);
    };
  }
  return imports;
}

function put(bytes) {
  const ptr = wasm.pendulum_alloc(bytes.length);
  new Uint8Array(wasm.memory.buffer, ptr, bytes.length).set(bytes);
  return [ptr, bytes.length];
}

function putSamples(samples) {
  const bytes = samples.length * 4;
  const ptr = wasm.pendulum_alloc(bytes);
  new Float32Array(wasm.memory.buffer, ptr, samples.length).set(samples);
  return [ptr, bytes];
}

function reply(ptr) {
  const length = new DataView(wasm.memory.buffer).getUint32(ptr, true);
  const text = decoder.decode(new Uint8Array(wasm.memory.buffer, ptr + 4, length));
  wasm.pendulum_free(ptr, length + 4);
  const parsed = JSON.parse(text);
  if (parsed.error) throw new PendulumError(parsed.error);
  return parsed;
}

const take = (ptr) => reply(ptr).ok;

/** One request: `{command: "period", length_m: 0.994, amplitude_deg: 2}`. */
export function call(request) {
  const [ptr, len] = put(encoder.encode(JSON.stringify(request)));
  try {
    return take(wasm.pendulum_call(ptr, len));
  } finally {
    wasm.pendulum_free(ptr, len);
  }
}

/**
 * A whole recording: `listen` of its samples (mono Float32Array). Returns
 * `{result, words, ticks}`: the command line's JSON, the sentences its
 * text ends with (warnings, findings, advice), and the ticks by column.
 */
export function listen(samples, sampleRate, options = {}) {
  const [optr, olen] = put(encoder.encode(JSON.stringify(options)));
  const [sptr, slen] = putSamples(samples);
  try {
    const r = reply(wasm.pendulum_listen(optr, olen, sptr, samples.length, sampleRate));
    return { result: r.ok, words: r.words, ticks: r.ticks };
  } finally {
    wasm.pendulum_free(sptr, slen);
    wasm.pendulum_free(optr, olen);
  }
}

/**
 * The channel (from 0) whose ticks stand out clearest, from the first
 * 30 s of each (Float32Arrays), as the command line chooses for a file.
 */
export function clearestChannel(channels, sampleRate) {
  if (channels.length < 2) return 0;
  const frames = Math.min(30 * sampleRate, ...channels.map((c) => c.length));
  const all = new Float32Array(frames * channels.length);
  channels.forEach((c, i) => all.set(c.subarray(0, frames), i * frames));
  const [ptr, bytes] = putSamples(all);
  try {
    return take(wasm.pendulum_clearest(ptr, frames, channels.length, sampleRate)).channel;
  } finally {
    wasm.pendulum_free(ptr, bytes);
  }
}

/**
 * A measurement file fitted as the lab's `fit decay`, `fit trajectory` or
 * `fit period` (`request.fit`), its bytes a Uint8Array. Returns
 * `{result, figure, warnings, notes}`: the command line's JSON, its plot
 * as panels of series, the warnings' sentences, and what the reader left
 * out.
 */
export function fit(request, bytes) {
  const [rptr, rlen] = put(encoder.encode(JSON.stringify(request)));
  const [fptr, flen] = put(bytes);
  try {
    const r = reply(wasm.pendulum_fit(rptr, rlen, fptr, flen));
    return { result: r.ok, figure: r.figure, warnings: r.warnings, notes: r.notes };
  } finally {
    wasm.pendulum_free(fptr, flen);
    wasm.pendulum_free(rptr, rlen);
  }
}

/** Listening as the samples come: push blocks, then finish. */
export class Live {
  constructor(sampleRate, options = {}) {
    const [ptr, len] = put(encoder.encode(JSON.stringify(options)));
    try {
      this.handle = take(wasm.pendulum_live_new(ptr, len, sampleRate)).handle;
    } finally {
      wasm.pendulum_free(ptr, len);
    }
  }

  /** The windows the samples complete, and a first reading once. */
  push(samples) {
    const [ptr, bytes] = putSamples(samples);
    try {
      return take(wasm.pendulum_live_push(this.handle, ptr, samples.length));
    } finally {
      wasm.pendulum_free(ptr, bytes);
    }
  }

  /** The whole recording's analysis, as `listen` returns it. */
  finish() {
    const r = reply(wasm.pendulum_live_finish(this.handle));
    return { result: r.ok, words: r.words, ticks: r.ticks };
  }
}
