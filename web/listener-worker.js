// The live listener off the page's thread: the microphone's reader posts
// each block here and goes back to reading at once, so that no block is
// dropped while the library works (a second's analysis when the first
// 30 s are learnt).
//
// Where the browser loses sound (its timestamps jump), the samples on
// either side have no known time between them: the listening is cut
// there and starts again, as the clock doctor cuts around a strike, and
// each stretch is read on its own. The end's figures are the longest
// stretch's; the others' rates are reported beside them.
import { load, Live, PendulumError } from "./pendulum.js";

let live = null;
let rate = 0;
let options = {};
/** Seconds fed before the current stretch, and in it. */
let offset = 0;
let fed = 0;
/** The stretches ended: {start_s, seconds, heard} or {start_s, seconds, error}. */
let pieces = [];
const ready = load();

const message = (e) => (e instanceof PendulumError ? e.message : String(e));

/** Ends the current stretch into `pieces`. */
function endPiece() {
  if (!live) return;
  const piece = { start_s: offset, seconds: fed };
  try {
    piece.heard = live.finish();
  } catch (e) {
    piece.error = message(e);
  }
  pieces.push(piece);
  live = null;
  offset += fed;
  fed = 0;
}

self.onmessage = async ({ data }) => {
  await ready;
  try {
    if (data.type === "start") {
      ({ rate, options } = data);
      pieces = [];
      offset = 0;
      fed = 0;
      live = new Live(rate, options);
    } else if (data.type === "push") {
      live ??= new Live(rate, options);
      fed += data.samples.length / rate;
      const pushed = live.push(data.samples);
      // Windows in the time of the whole listening (sound received).
      for (const w of pushed.windows) {
        w.start_s += offset;
        w.end_s += offset;
      }
      if (pushed.windows.length || pushed.provisional) self.postMessage({ type: "pushed", pushed });
    } else if (data.type === "gap") {
      endPiece();
    } else if (data.type === "finish") {
      endPiece();
      const read = pieces.filter((p) => p.heard);
      if (!read.length) throw new Error(pieces.at(-1)?.error ?? "nothing was heard");
      const best = read.reduce((a, b) => (b.heard.result.beats > a.heard.result.beats ? b : a));
      const others = pieces.filter((p) => p !== best).map((p) => ({
        start_s: p.start_s,
        seconds: p.seconds,
        rate_s_per_day: p.heard?.result.rate_s_per_day ?? null,
        error: p.error ?? null,
      }));
      self.postMessage({ type: "finished", heard: best.heard, piece: { start_s: best.start_s, seconds: best.seconds }, others });
    }
  } catch (e) {
    live = null;
    self.postMessage({ type: "error", message: message(e) });
  }
};
