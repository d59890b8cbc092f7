// The live listener off the page's thread: the microphone's reader posts
// each block here and goes back to reading at once, so that no block is
// dropped while the library works (a second's analysis when the first
// 30 s are learnt).
import { load, Live, PendulumError } from "./pendulum.js";

let live = null;
const ready = load();

self.onmessage = async ({ data }) => {
  await ready;
  try {
    if (data.type === "start") {
      live = new Live(data.rate, data.options);
    } else if (data.type === "push") {
      const pushed = live.push(data.samples);
      if (pushed.windows.length || pushed.provisional) self.postMessage({ type: "pushed", pushed });
    } else if (data.type === "finish") {
      self.postMessage({ type: "finished", heard: live.finish() });
      live = null;
    }
  } catch (e) {
    live = null;
    self.postMessage({ type: "error", message: e instanceof PendulumError ? e.message : String(e) });
  }
};
