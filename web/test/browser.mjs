// The page in a real browser (Debian's chromium through the DevTools
// protocol, puppeteer-core): every calculator against the command line's
// --json, recordings opened in the timegrapher against `pendulum listen`,
// the microphone (a WAV given to chromium as a fake microphone) against
// the same, a reload offline, and no console errors. Screenshots of each
// room at a phone's and a laptop's width go to $SHOTS if set.
//
//   node web/test/browser.mjs            (after web/build.sh and cargo build --release)
import puppeteer from "puppeteer-core";
import { execFileSync, spawnSync } from "node:child_process";
import { createServer } from "node:http";
import { mkdtempSync, readFileSync, writeFileSync, existsSync } from "node:fs";
import { tmpdir } from "node:os";
import { join, extname, resolve, dirname, basename } from "node:path";

const root = resolve(new URL("../..", import.meta.url).pathname);
const dist = join(root, "web/dist");
const bin = join(root, "target/release/pendulum");
const browserPath = ["/usr/bin/chromium", "/usr/bin/chromium-browser", "/usr/bin/google-chrome"].find(existsSync);
if (!browserPath) throw new Error("the page's browser tests need chromium (apt-get install chromium)");
const work = mkdtempSync(join(tmpdir(), "pendulum-web-"));
let failures = 0;
const check = (ok, what) => {
  console.log(`${ok ? "ok  " : "FAIL"} ${what}`);
  if (!ok) failures++;
};
const cli = (...args) => JSON.parse(execFileSync(bin, [...args, "--json"], { encoding: "utf8" }));

// A static server of web/dist (a service worker needs http).
const types = { ".html": "text/html", ".js": "text/javascript", ".css": "text/css", ".wasm": "application/wasm", ".svg": "image/svg+xml", ".webmanifest": "application/manifest+json" };
const server = createServer((req, res) => {
  // (The test's own files, recordings made here, under /work/.)
  const name = decodeURIComponent(new URL(req.url, "http://x").pathname);
  const [from, rest] = name.startsWith("/work/") ? [work, name.slice(5)] : [dist, name];
  const path = join(from, rest.replace(/\/$/, "/index.html"));
  if (!path.startsWith(from) || !existsSync(path)) { res.writeHead(404); res.end(); return; }
  res.writeHead(200, { "content-type": types[extname(path)] ?? "application/octet-stream" });
  res.end(readFileSync(path));
});
await new Promise((r) => server.listen(0, "127.0.0.1", r));
const base = `http://127.0.0.1:${server.address().port}/`;

function launch(extra = []) {
  return puppeteer.launch({
    executablePath: browserPath,
    headless: true,
    args: ["--no-sandbox", "--disable-gpu", "--use-fake-ui-for-media-stream", ...extra],
  });
}

async function open(browser, hash, width = 1280, height = 800) {
  const page = await browser.newPage();
  const errors = [];
  page.on("console", (m) => { if (m.type() === "error") errors.push(m.text()); });
  page.on("pageerror", (e) => errors.push(String(e)));
  await page.setViewport({ width, height });
  await page.goto(base + "index.html" + hash);
  await page.waitForSelector("body[data-ready]", { timeout: 20000 });
  return { page, errors };
}

/**
 * Where two JSON values differ (paths): numbers to 1e-12 of their size
 * (the browser's sin, log and the like are Rust's own, the binary's
 * glibc's: they differ in the last bit or two), all else exactly. An
 * iterative fit's stopping point moves with those last bits, so its
 * figures are compared to `FITTED` instead.
 */
const EXACT = { relative: 1e-12, absolute: 0 };
/** 1e-6 of a figure's size, or 1e-9 absolute near zero: a hundredth of
 * a standard error or less. (Measured: 2.5e-8 at most, in the poorly
 * determined rival laws of a run-down; 1e-11 in the preferred ones.) */
const FITTED = { relative: 1e-6, absolute: 1e-9 };
const near = (a, b, tol = EXACT) => Math.abs(a - b) <= tol.relative * Math.max(Math.abs(a), Math.abs(b)) + tol.absolute;
function differences(a, b, path = "", tol = EXACT) {
  if (Array.isArray(a) && Array.isArray(b)) {
    if (a.length !== b.length) return [`${path} (length ${a.length}, ${b.length})`];
    return a.flatMap((x, i) => differences(x, b[i], `${path}[${i}]`, tol));
  }
  if (a && b && typeof a === "object" && typeof b === "object") {
    const keys = new Set([...Object.keys(a), ...Object.keys(b)]);
    return [...keys].flatMap((k) => (k in a && k in b ? differences(a[k], b[k], `${path}.${k}`, tol) : [`${path}.${k} (only in ${k in a ? "the page" : "the command line"})`]));
  }
  const close = typeof a === "number" && typeof b === "number" && near(a, b, tol);
  return a === b || close ? [] : [`${path} (${JSON.stringify(a)}, ${JSON.stringify(b)})`];
}

const value = (page, selector) => page.$eval(selector, (el) => (el.dataset.value === undefined ? null : Number(el.dataset.value)));

// ---- Calculators: equal to the command line to the last digit ----------
const calculators = [
  { command: "period", fields: { length_m: "0.99362", amplitude_deg: "3", latitude_deg: "" },
    args: ["period", "--length", "0.99362m", "--amplitude", "3deg"], keys: ["period_s", "circular_error_s_per_day", "beats_per_hour"] },
  { command: "period", fields: { length_m: "0.2485", amplitude_deg: "12", latitude_deg: "48.2" },
    args: ["period", "--length", "0.2485m", "--amplitude", "12deg", "--latitude", "48.2deg"], keys: ["period_s", "circular_error_s_per_day", "g_m_s2"] },
  { command: "length", fields: { bph: "5400", amplitude_deg: "4", latitude_deg: "" },
    args: ["length", "--bph", "5400", "--amplitude", "4deg"], keys: ["length_m", "period_s"] },
  { command: "regulate", fields: { rate_s_per_day: "-42", length_m: "0.994", nut_tpi: "32" },
    args: ["regulate", "--rate", "-42", "--length", "0.994m", "--nut-tpi", "32"], keys: ["shift_m", "nut_turns"] },
  { command: "gravity", fields: { latitude_deg: "35.68", height_m: "40" },
    args: ["gravity", "--latitude", "35.68deg", "--height", "40m"], keys: ["g_m_s2"] },
  { command: "damped", fields: { length_m: "0.994", amplitude_deg: "5", q: "3000" },
    args: ["damped", "--length", "0.994m", "--amplitude", "5deg", "--q", "3000"], keys: ["damped_period_s", "decay_time_s", "q_factor"] },
];

const browser = await launch();
{
  const { page, errors } = await open(browser, "#calculators");
  for (const c of calculators) {
    const form = `form[data-command="${c.command}"]`;
    for (const [name, text] of Object.entries(c.fields)) {
      await page.$eval(`${form} input[name="${name}"]`, (el, t) => { el.value = t; el.dispatchEvent(new Event("input", { bubbles: true })); }, text);
    }
    const expected = cli(...c.args);
    for (const key of c.keys) {
      const got = await value(page, `${form} [data-key="${key}"]`);
      check(got === expected[key], `${c.args.join(" ")}: ${key} page ${got}, command line ${expected[key]}`);
    }
  }
  // Whole answers: the page's library against the binary, every key.
  for (const c of calculators) {
    const request = { command: c.command };
    for (const [name, text] of Object.entries(c.fields)) if (text !== "") request[name] = Number(text);
    const page_json = await page.evaluate(async (r) => {
      const m = await import("./pendulum.js");
      await m.load();
      return m.call(r);
    }, request);
    const diff = differences(page_json, cli(...c.args));
    check(diff.length === 0, `${c.args.join(" ")}: the whole answer the command line's${diff.length ? ` (differs at ${diff.slice(0, 5).join(", ")})` : ""}`);
  }
  // A refusal reads as the command line's sentence.
  await page.$eval(`form[data-command="period"] input[name="length_m"]`, (el) => { el.value = "-1"; el.dispatchEvent(new Event("input", { bubbles: true })); });
  const refusal = await page.$eval(`form[data-command="period"] dd.error`, (el) => el.textContent);
  check(/^--length: must be positive, got -1/.test(refusal), `a negative length refused: "${refusal}"`);
  // A field that is not a number is refused in its own words.
  await page.$eval(`form[data-command="period"] input[name="length_m"]`, (el) => { el.value = "abc"; el.dispatchEvent(new Event("input", { bubbles: true })); });
  const notNumber = await page.$eval(`form[data-command="period"] dd.error`, (el) => el.textContent);
  check(notNumber === "Length, m: must be a finite number, got abc", `a length of "abc" refused: "${notNumber}"`);
  check(errors.length === 0, `no console errors on the calculators (${errors.join("; ")})`);
  await page.close();
}

// ---- Lab: files fitted as the command line fits them ----------------------
// Real files (crates/pendulum-cli/tests/data/real, their sources in its
// README), a published table, a workbook and a pasted table; each given to
// the page through its file input and to the binary by the same name (run
// in the file's folder), so the whole JSON can be compared.
const data = join(root, "crates/pendulum-cli/tests/data");
const pasted = "time_s,amplitude_deg\n0,10\n20,9.1\n40,8.3\n60,7.55\n80,6.9\n100,6.3\n120,5.72\n140,5.2\n160,4.75\n180,4.33\n";
writeFileSync(join(work, "pasted table"), pasted);
const preferred = (j) => j.models.find((m) => m.model === j.preferred);
const labCases = [
  { name: "a Tracker project's run-down from 80°", fit: "decay", file: join(data, "real/pendulum_fullPeriod.trk"), fields: {}, args: [],
    figures: (j) => ({ omega_rad_s: j.omega_rad_s, q_factor: preferred(j).q_factor }) },
  { name: "a Tracker project's swing, the pivot fitted", fit: "trajectory", file: join(data, "real/pendulum_length2.trk"), fields: { pivot: "fit" }, args: ["--pivot", "fit"],
    figures: (j) => ({ g_m_s2: j.parameters.g_m_s2, omega_n_rad_s: j.parameters.omega_n_rad_s, length_m: j.length_m }) },
  { name: "a published table of periods (Silveira 1986)", fit: "period", file: join(data, "period/silveira1986.csv"), fields: {}, args: [],
    figures: (j) => ({ small_angle_period_s: j.parameters.small_angle_period_s, circular_error_coefficient: j.parameters.circular_error_coefficient }) },
  { name: "a phyphox gyroscope workbook", fit: "trajectory", file: join(data, "gyroscope/gyroscope.xls"), fields: {}, args: [],
    figures: (j) => ({ omega_n_rad_s: j.parameters.omega_n_rad_s }) },
  { name: "a phyphox gyroscope CSV", fit: "trajectory", file: join(data, "gyroscope/gyroscope-comma.csv"), fields: {}, args: [],
    figures: (j) => ({ omega_n_rad_s: j.parameters.omega_n_rad_s, zeta: j.parameters.zeta }) },
  // More files, given as LAB_FILES=fit:path,… (real records whose
  // licence keeps them out of the repository).
  ...(process.env.LAB_FILES ?? "").split(",").filter(Boolean).map((spec) => {
    const [fit, file] = spec.split(":");
    return { name: basename(file), fit, file, fields: {}, args: [], figures: () => ({}) };
  }),
  { name: "a pasted table of amplitudes", fit: "decay", paste: pasted, file: join(work, "pasted table"), fields: { length_m: "0.994" }, args: ["--length", "0.994m"],
    figures: (j) => ({ q_factor: preferred(j).q_factor }) },
];
const cliIn = (file, args) => JSON.parse(execFileSync(bin, ["fit", ...args, basename(file), "--json"], { encoding: "utf8", cwd: dirname(file) }));
async function labFit(page, c) {
  const before = await page.evaluate(() => document.body.dataset.fitted ?? "0");
  await page.select("#lab-form select[name=fit]", c.fit);
  for (const name of ["length_m", "length_uncertainty_m", "pivot", "columns"]) {
    await page.$eval(`#lab-form [name="${name}"]`, (el, t) => { el.value = t; }, c.fields[name] ?? "");
  }
  if (c.paste !== undefined) {
    await page.$eval("#lab-paste", (el, t) => { el.value = t; }, c.paste);
    await page.click("#lab-paste-fit");
  } else {
    await (await page.$("#lab-file")).uploadFile(c.file);
  }
  await page.waitForFunction((b) => (document.body.dataset.fitted ?? "0") !== b, { timeout: 120000 }, before);
  return page.$eval("#lab-error", (el) => (el.hidden ? "" : el.textContent));
}
{
  const { page, errors } = await open(browser, "#lab");
  for (const c of labCases) {
    const shown = await labFit(page, c);
    const expected = cliIn(c.file, [c.fit, ...c.args]);
    check(shown === "", `lab, ${c.name}: fitted${shown ? ` (refused: ${shown})` : ""}`);
    for (const [key, want] of Object.entries(c.figures(expected))) {
      const got = await value(page, `#lab-figures [data-key="${key}"]`);
      check(got !== null && near(got, want, FITTED), `lab, ${c.name}: ${key} page ${got}, command line ${want}`);
    }
    const whole = JSON.parse(await page.$eval("#lab-json", (el) => el.textContent));
    const diff = differences(whole, expected, "", FITTED);
    check(diff.length === 0, `lab, ${c.name}: the whole result the command line's${diff.length ? ` (differs at ${diff.slice(0, 5).join(", ")})` : ""}`);
    // The figure drawn: a dot for every point of its data series.
    const [dots, circles] = await page.evaluate(async (req) => {
      const svg = document.querySelector("#lab-plot svg");
      return [Number(svg.dataset.dots), svg.querySelectorAll("circle").length];
    });
    check(dots > 0 && circles >= dots, `lab, ${c.name}: the figure draws its ${dots} data points (${circles} dots, legend's included)`);
  }
  // The figure's points saved as CSV: a row a point.
  {
    const downloads = mkdtempSync(join(tmpdir(), "pendulum-downloads-"));
    const client = await page.createCDPSession();
    await client.send("Browser.setDownloadBehavior", { behavior: "allow", downloadPath: downloads });
    await page.click("#lab-save-csv");
    await page.click("#lab-save-svg");
    const csv = join(downloads, "fit.csv");
    const svg = join(downloads, "fit.svg");
    for (let i = 0; i < 100 && !(existsSync(csv) && existsSync(svg)); i++) await new Promise((r) => setTimeout(r, 100));
    const points = await page.evaluate(() => Number(document.querySelector("#lab-plot svg").dataset.points));
    const rows = existsSync(csv) ? readFileSync(csv, "utf8").trim().split("\n").length - 1 : -1;
    check(rows === points, `lab: the figure's CSV holds its ${points} points (${rows} rows)`);
    const saved = existsSync(svg) ? readFileSync(svg, "utf8") : "";
    check(saved.startsWith("<?xml") && saved.includes("<svg") && saved.includes("Amplitude decay"), "lab: the figure saved as an SVG file");
  }
  // Refusals in the command line's words: a file without numbers, and a
  // length's uncertainty without the length.
  for (const [c, args] of [
    [{ fit: "decay", paste: "hello\nworld\n", fields: {} }, ["decay"]],
    [{ fit: "decay", file: join(data, "real/pendulum_fullPeriod.trk"), fields: { length_uncertainty_m: "0.002" } }, ["decay", "--length-uncertainty", "0.002m"]],
  ]) {
    const file = c.paste !== undefined ? join(work, "pasted table") : c.file;
    if (c.paste !== undefined) writeFileSync(file, c.paste);
    const shown = await labFit(page, c);
    const run = spawnSync(bin, ["fit", ...args, basename(file)], { encoding: "utf8", cwd: dirname(file) });
    const theirs = run.stderr.trim().replace(/^error: /, "");
    check(shown !== "" && shown === theirs, `lab refuses as the command line does: page "${shown}", command line "${theirs}"`);
  }
  check(errors.length === 0, `no console errors in the lab (${errors.join("; ")})`);
  await page.close();
}

// ---- Timegrapher: a recording opened ----------------------------------
const recordings = [
  { name: "seconds-clock", bph: 3600, seconds: 240, every: "60" },
  { name: "bracket-clock", bph: 5400, seconds: 180, every: "60" },
  { name: "watch", bph: 28800, seconds: 60, every: "10" },
];
for (const r of recordings) {
  r.path = join(work, `${r.name}.wav`);
  execFileSync(bin, ["synth", "ticks", r.path, "--bph", String(r.bph), "--duration", `${r.seconds}s`, "--rate", "7", "--beat-error", "0.8", "--seed", "5"]);
}
{
  const { page, errors } = await open(browser, "#timegrapher");
  for (const r of recordings) {
    await page.evaluate(() => { delete document.body.dataset.heard; });
    await page.$eval(`#listen-form input[name="every_s"]`, (el, t) => { el.value = t; }, r.every);
    const input = await page.$("#listen-file");
    await input.uploadFile(r.path);
    await page.waitForSelector("body[data-heard]", { timeout: 120000 });
    const expected = cli("listen", r.path, "--every", `${r.every}s`);
    const rate = await value(page, "#out-rate");
    const beatError = await value(page, "#out-beat-error");
    const se = expected.rate_s_per_day_se ?? expected.rate_se_s_per_day;
    check(Math.abs(rate - expected.rate_s_per_day) <= se, `${r.name}: rate page ${rate}, command line ${expected.rate_s_per_day} ± ${se}`);
    check(Math.abs(beatError - expected.beat_error_ms) <= (expected.beat_error_se_ms ?? 0.01), `${r.name}: beat error page ${beatError}, command line ${expected.beat_error_ms}`);
    // The whole result, but for the file's name and channel (the page
    // has no file on disk).
    const whole = JSON.parse(await page.$eval("#whole-json", (el) => el.textContent));
    const { file, channel, ...listened } = expected;
    const diff = differences(whole, listened);
    check(diff.length === 0, `${r.name}: the whole result the command line's${diff.length ? ` (differs at ${diff.slice(0, 5).join(", ")})` : ""}`);
    const rows = await page.$$eval("#windows tbody tr", (tr) => tr.length);
    check(rows === expected.windows.length, `${r.name}: ${rows} windows shown, the command line's ${expected.windows.length}`);
  }
  // The ticks saved: the command line's --ticks file, cell for cell.
  {
    const last = recordings[recordings.length - 1];
    const downloads = mkdtempSync(join(tmpdir(), "pendulum-downloads-"));
    const client = await page.createCDPSession();
    await client.send("Browser.setDownloadBehavior", { behavior: "allow", downloadPath: downloads });
    await page.click("#save-ticks");
    const saved = join(downloads, "ticks.csv");
    for (let i = 0; i < 100 && !existsSync(saved); i++) await new Promise((r) => setTimeout(r, 100));
    const theirs = join(work, "ticks.csv");
    execFileSync(bin, ["listen", last.path, "--every", `${last.every}s`, "--ticks", theirs]);
    const rows = (f) => readFileSync(f, "utf8").trim().split("\n").map((l) => l.split(","));
    const [a, b] = [existsSync(saved) ? rows(saved) : [], rows(theirs)];
    const cells = a.length === b.length && a.every((row, i) => row.every((c, j) => c === b[i][j] || Math.abs(Number(c) - Number(b[i][j])) <= 1e-12 * Math.abs(Number(c))));
    check(cells, `${last.name}: the ticks saved (${a.length} rows) are the command line's --ticks file (${b.length} rows)`);
  }
  // Stereo with a louder channel of noise: the clearer channel is taken,
  // as the command line takes it.
  {
    const mono = readFileSync(recordings[2].path);
    const frames = (mono.length - 44) / 2;
    const stereo = Buffer.alloc(44 + frames * 4);
    mono.copy(stereo, 0, 0, 44);
    stereo.writeUInt32LE(36 + frames * 4, 4);
    stereo.writeUInt16LE(2, 22);
    stereo.writeUInt32LE(mono.readUInt32LE(24) * 4, 28);
    stereo.writeUInt16LE(4, 32);
    stereo.writeUInt32LE(frames * 4, 40);
    let seed = 12345;
    for (let i = 0; i < frames; i++) {
      seed = (seed * 1103515245 + 12345) % 2147483648;
      stereo.writeInt16LE(Math.round((seed / 2147483648 - 0.5) * 40000), 44 + 4 * i);
      stereo.writeInt16LE(mono.readInt16LE(44 + 2 * i), 44 + 4 * i + 2);
    }
    const path = join(work, "stereo.wav");
    writeFileSync(path, stereo);
    await page.evaluate(() => { delete document.body.dataset.heard; });
    await (await page.$("#listen-file")).uploadFile(path);
    await page.waitForSelector("body[data-heard]", { timeout: 120000 });
    const expected = cli("listen", path, "--every", "10s");
    const channel = await page.evaluate(() => Number(document.body.dataset.channel));
    const rate = await value(page, "#out-rate");
    check(channel === expected.channel && rate === expected.rate_s_per_day, `stereo, channel 1 noise: the page took channel ${channel} (rate ${rate}), the command line channel ${expected.channel} (rate ${expected.rate_s_per_day})`);
  }
  // Sound the browser loses (the microphone's timestamps jump): the
  // listener is cut there and each stretch read on its own, as the doctor
  // cuts around a strike. The watch fed to the page's worker as the
  // microphone's reader feeds it, 7 ms lost at 25 s: the figures are the
  // longest stretch's, its rate the whole file's within its standard
  // errors, the other stretch's rate beside it.
  {
    const watch = recordings[2];
    const cut = await page.evaluate(async (name) => {
      const { readWav } = await import("./app.js");
      const wav = readWav(await (await fetch(`work/${name}`)).arrayBuffer());
      const x = wav.channels[0], rate = wav.rate;
      const worker = new Worker("listener-worker.js", { type: "module" });
      const done = new Promise((resolve) => {
        worker.onmessage = ({ data }) => { if (data.type === "finished" || data.type === "error") resolve(data); };
      });
      worker.postMessage({ type: "start", rate, options: { every_s: 10 } });
      const block = Math.round(rate / 100), lost = Math.round(0.007 * rate), at = 25 * rate;
      for (let i = 0; i + block <= x.length; i += block) {
        if (i <= at && at < i + block) { worker.postMessage({ type: "gap" }); i += lost; }
        worker.postMessage({ type: "push", samples: x.slice(i, i + block) });
      }
      worker.postMessage({ type: "finish" });
      const data = await done;
      worker.terminate();
      return data;
    }, basename(watch.path));
    const expected = cli("listen", watch.path);
    const se = expected.rate_se_s_per_day;
    const rate = cut.heard?.result.rate_s_per_day;
    const other = cut.others?.[0]?.rate_s_per_day;
    check(cut.type === "finished" && Math.abs(rate - expected.rate_s_per_day) <= 3 * Math.hypot(se, cut.heard.result.rate_se_s_per_day) && cut.others.length === 1,
      `7 ms of sound lost at 25 s: cut there, the longer stretch (from ${cut.piece?.start_s} s, ${cut.piece?.seconds} s) reads ${rate} s/day, the file ${expected.rate_s_per_day} ± ${se}; the other stretch ${other} s/day ${cut.message ?? ""}`);
    check(Math.abs(other - expected.rate_s_per_day) <= 0.05, `the other stretch's rate ${other} s/day is the file's too`);
  }
  check(errors.length === 0, `no console errors in the timegrapher (${errors.join("; ")})`);
  // Offline: the page comes back from its cache.
  await page.waitForFunction(() => navigator.serviceWorker?.controller || navigator.serviceWorker.ready, { timeout: 20000 });
  await page.evaluate(() => navigator.serviceWorker.ready);
  await page.reload();
  await page.waitForSelector("body[data-ready]", { timeout: 20000 });
  await page.setOfflineMode(true);
  await page.reload();
  const offline = await page.waitForSelector("body[data-ready]", { timeout: 20000 }).then(() => true, () => false);
  check(offline, "a reload offline still works");
  await page.close();
}

// ---- Screenshots ----------------------------------------------------------
if (process.env.SHOTS) {
  for (const [label, width, height] of [["phone", 390, 844], ["laptop", 1280, 860]]) {
    for (const room of ["timegrapher", "lab", "calculators"]) {
      const { page } = await open(browser, `#${room}`, width, height);
      if (room === "timegrapher") {
        await (await page.$("#listen-file")).uploadFile(recordings[2].path);
        await page.waitForSelector("body[data-heard]", { timeout: 120000 });
      }
      if (room === "lab") await labFit(page, labCases[0]);
      await page.screenshot({ path: join(process.env.SHOTS, `${room}-${label}.png`), fullPage: true });
      await page.close();
    }
  }
}
await browser.close();

// ---- The microphone: a recording played as a fake microphone --------------
{
  const watch = recordings[2];
  const mic = await launch(["--use-fake-device-for-media-stream", `--use-file-for-fake-audio-capture=${watch.path}%noloop`]);
  const { page, errors } = await open(mic, "#timegrapher");
  await page.$eval(`#listen-form input[name="every_s"]`, (el) => { el.value = "10"; });
  await page.click("#mic-start");
  await new Promise((r) => setTimeout(r, 42000));
  await page.click("#mic-stop");
  await page.waitForSelector("body[data-heard]", { timeout: 30000 }).catch(() => {});
  const expected = cli("listen", watch.path);
  const rate = await value(page, "#out-rate");
  const shown = await page.$eval("#listen-error", (el) => (el.hidden ? "" : el.textContent));
  const fed = await page.evaluate(() => `${document.body.dataset.micS} s fed, ${document.body.dataset.micGaps} gaps cut`);
  const se = expected.rate_se_s_per_day;
  // (Fewer seconds than the file: the standard error allowed is ×3.)
  check(rate !== null && Math.abs(rate - expected.rate_s_per_day) <= 3 * se + 0.05, `microphone: rate ${rate}, the file's ${expected.rate_s_per_day} ± ${se} (${fed}) ${shown}`);
  check(errors.length === 0, `no console errors listening to the microphone (${errors.join("; ")})`);
  await mic.close();
}
server.close();
if (failures) {
  console.error(`${failures} browser check(s) failed`);
  process.exit(1);
}
console.log("all browser checks passed");
