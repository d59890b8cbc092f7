// The page's speed in Debian's chromium (headless, on this machine):
// the WebAssembly module's size, the time from loading the page to the
// calculators' first answers, and the live listener's pace on an hour of
// a 28,800 bph watch at 48 kHz pushed in blocks of 0.1 s, as the
// microphone gives them (the blocks converted from the WAV's 16 bits
// one at a time, as they come); and the lab's fits of the real Tracker
// projects in the page beside the binary's on the same files.
//
//   bash web/build.sh && cargo build --release && (cd web/test && npm ci)
//   node bench/web.mjs
import puppeteer from "../web/test/node_modules/puppeteer-core/lib/puppeteer/puppeteer-core.js";
import { execFileSync } from "node:child_process";
import { createServer } from "node:http";
import { createReadStream, existsSync, mkdtempSync, readFileSync, statSync } from "node:fs";
import { gzipSync } from "node:zlib";
import { tmpdir } from "node:os";
import { join, extname, resolve } from "node:path";

const root = resolve(new URL("..", import.meta.url).pathname);
const dist = join(root, "web/dist");
const work = mkdtempSync(join(tmpdir(), "pendulum-bench-"));
const wasm = readFileSync(join(dist, "pendulum.wasm"));
console.log(`module: ${(wasm.length / 1e6).toFixed(2)} MB, ${(gzipSync(wasm, { level: 9 }).length / 1e6).toFixed(2)} MB gzipped`);

const real = join(root, "crates/pendulum-cli/tests/data/real");
const hour = join(work, "hour.wav");
execFileSync(join(root, "target/release/pendulum"), ["synth", "ticks", hour, "--bph", "28800", "--duration", "1h", "--sample-rate", "48000", "--rate", "5", "--beat-error", "0.6", "--seed", "3"]);
const types = { ".html": "text/html", ".js": "text/javascript", ".css": "text/css", ".wasm": "application/wasm", ".svg": "image/svg+xml" };
const server = createServer((req, res) => {
  const name = new URL(req.url, "http://x").pathname;
  const path = name === "/hour.wav" ? hour : name.startsWith("/real/") ? join(real, name.slice(6)) : join(dist, name === "/" ? "index.html" : name);
  if (!existsSync(path)) { res.writeHead(404); res.end(); return; }
  res.writeHead(200, { "content-type": types[extname(path)] ?? "application/octet-stream", "content-length": statSync(path).size });
  createReadStream(path).pipe(res);
});
await new Promise((r) => server.listen(0, "127.0.0.1", r));
const base = `http://127.0.0.1:${server.address().port}/`;
const browser = await puppeteer.launch({ executablePath: "/usr/bin/chromium", headless: true, args: ["--no-sandbox", "--disable-gpu"] });

// First answers: three fresh loads.
for (let i = 0; i < 3; i++) {
  const context = await browser.createBrowserContext();
  const page = await context.newPage();
  await page.goto(base + "index.html#calculators");
  await page.waitForSelector("body[data-ready]");
  const ms = await page.evaluate(() => performance.getEntriesByName("first-answer")[0].startTime);
  console.log(`calculators' first answers ${ms.toFixed(0)} ms after the page began loading`);
  await context.close();
}

// The listener's pace on an hour at 48 kHz.
const page = await browser.newPage();
await page.goto(base + "index.html");
await page.waitForSelector("body[data-ready]");
const result = await page.evaluate(async () => {
  const m = await import("./pendulum.js");
  await m.load();
  const buffer = await (await fetch("hour.wav")).arrayBuffer();
  const v = new DataView(buffer);
  let at = 12, rate = 0, data = 0, size = 0;
  while (at + 8 <= buffer.byteLength) {
    const id = String.fromCharCode(...new Uint8Array(buffer, at, 4)), n = v.getUint32(at + 4, true);
    if (id === "fmt ") rate = v.getUint32(at + 12, true);
    if (id === "data") { data = at + 8; size = n; break; }
    at += 8 + n + (n % 2);
  }
  const pcm = new Int16Array(buffer, data, size / 2);
  const live = new m.Live(rate, { every_s: 300 });
  const block = rate / 10, samples = new Float32Array(block);
  const start = performance.now();
  let windows = 0;
  for (let i = 0; i + block <= pcm.length; i += block) {
    for (let j = 0; j < block; j++) samples[j] = pcm[i + j] / 32768;
    windows += live.push(samples).windows.length;
  }
  const end = live.finish();
  return { seconds: (performance.now() - start) / 1000, heard: pcm.length / rate, windows, rate: end.result.rate_s_per_day, beats: end.result.beats, missed: end.result.missed };
});
console.log(`an hour of a 28,800 bph watch at 48 kHz, live in 0.1 s blocks: ${result.seconds.toFixed(2)} s (${(result.heard / result.seconds).toFixed(0)} times real time), ${result.beats} beats, ${result.missed} missed, rate ${result.rate.toFixed(5)} s/day (truth 5), ${result.windows} windows printed as they came`);

// The lab: each fit in the page (the file's bytes already fetched) and by
// the binary (its whole run, from its start), three times each.
const fits = [
  ["decay", "pendulum_fullPeriod.trk", {}, []],
  ["trajectory", "pendulum_length2.trk", { pivot: "fit" }, ["--pivot", "fit"]],
];
for (const [fit, file, options, args] of fits) {
  const ms = await page.evaluate(async (fit, file, options) => {
    const m = await import("./pendulum.js");
    const bytes = new Uint8Array(await (await fetch(`real/${file}`)).arrayBuffer());
    const times = [];
    for (let i = 0; i < 3; i++) {
      const start = performance.now();
      m.fit({ fit, file_name: file, ...options }, bytes);
      times.push(performance.now() - start);
    }
    return Math.min(...times);
  }, fit, file, options);
  const cliTimes = [];
  for (let i = 0; i < 3; i++) {
    const start = process.hrtime.bigint();
    execFileSync(join(root, "target/release/pendulum"), ["fit", fit, join(real, file), ...args, "--json"]);
    cliTimes.push(Number(process.hrtime.bigint() - start) / 1e6);
  }
  console.log(`lab: fit ${fit} ${file} in the page ${ms.toFixed(0)} ms, the binary ${Math.min(...cliTimes).toFixed(0)} ms`);
}
await browser.close();
server.close();
