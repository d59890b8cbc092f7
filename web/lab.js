// The lab: a measurement file (opened, dropped or pasted) fitted as the
// command line's `pendulum fit decay | trajectory | period` fits it, by the
// same library code; its figures with their JSON keys and full values as
// attributes, the plot the command line would draw, and both saved.
import { fit, PendulumError } from "./pendulum.js";
import { drawFigure, figureCsv } from "./figure.js";

const $ = (selector, root = document) => root.querySelector(selector);

/** The options each fit takes from the form (the others are not sent). */
const TAKES = {
  decay: ["length_m", "length_uncertainty_m", "pivot", "angle_unit", "columns"],
  trajectory: ["length_m", "length_uncertainty_m", "pivot", "angle_unit", "columns"],
  period: ["length_m", "length_uncertainty_m", "angle_unit", "columns"],
};
const NUMBERS = new Set(["length_m", "length_uncertainty_m"]);

let helpers = null;
let last = null;
let fits = 0;

/** The request of the form for a file called `name`. */
export function labRequest(form, name) {
  const kind = form.elements.fit.value;
  const req = { fit: kind, file_name: name };
  for (const key of TAKES[kind]) {
    const text = form.elements[key].value.trim();
    if (text === "") continue;
    req[key] = NUMBERS.has(key) ? helpers.number(form.elements[key]) : text;
  }
  return req;
}

function error(message) {
  const box = $("#lab-error");
  box.hidden = !message;
  box.textContent = message ?? "";
}

/** A figure: its words, its value (with key and full value), ± its error. */
function figureRow(dl, key, value, error, unitOverride) {
  if (value === null || value === undefined) return;
  const [words, unit] = helpers.named(key);
  const dt = document.createElement("dt");
  dt.textContent = words;
  const dd = document.createElement("dd");
  const v = document.createElement("span");
  helpers.show(v, key, value, 7);
  dd.append(v);
  if (typeof error === "number") {
    const e = document.createElement("span");
    e.className = "se";
    helpers.show(e, `${key}_standard_error`, error, 2);
    dd.append(" ± ", e);
  }
  const u = unitOverride ?? unit;
  if (u) dd.append(` ${u}`);
  dl.append(dt, dd);
}

function parameters(dl, params, errors = {}) {
  for (const [k, v] of Object.entries(params ?? {})) figureRow(dl, k, v, errors?.[k]);
}

function qRow(dl, q, se, lower) {
  if (typeof q === "number") figureRow(dl, "q_factor", q, se, "");
  else if (typeof lower === "number") {
    const dt = document.createElement("dt");
    dt.textContent = "Q";
    const dd = document.createElement("dd");
    const v = document.createElement("span");
    helpers.show(v, "q_factor_lower_bound", lower, 3);
    dd.append("more than ", v, " (no measurable loss over the record)");
    dl.append(dt, dd);
  }
}

function rivals(models, preferred) {
  const wrap = $("#lab-rivals");
  wrap.replaceChildren();
  if (!models?.length) return;
  const best = (models.find((m) => m.model === preferred) ?? models[0]).bic;
  const table = document.createElement("table");
  table.className = "windows";
  table.innerHTML = "<thead><tr><th>Damping law</th><th>Q</th><th>±</th><th>BIC − preferred's</th><th>Akaike weight</th></tr></thead>";
  const body = document.createElement("tbody");
  for (const m of [...models].sort((a, b) => a.bic - b.bic)) {
    const tr = document.createElement("tr");
    if (m.model === preferred) tr.className = "preferred";
    const cells = [[null, m.model + (m.model === preferred ? " (preferred)" : "")], ["q_factor", m.q_factor, 5], ["q_factor_standard_error", m.q_factor_standard_error, 2], ["delta_bic", m.bic - best, 3], ["akaike_weight", m.akaike_weight, 3]];
    for (const [key, value, digits] of cells) {
      const td = document.createElement("td");
      if (key === null) td.textContent = value;
      else helpers.show(td, key, value, digits);
      // A difference of BICs is read to a tenth.
      if (key === "delta_bic") td.textContent = (Math.abs(value) < 0.05 ? 0 : value).toFixed(1);
      tr.append(td);
    }
    body.append(tr);
  }
  table.append(body);
  wrap.append(table);
}

/** Shows a fit's reply. */
export function renderFit(kind, reply) {
  const r = reply.result;
  last = reply;
  $("#lab-result").hidden = false;
  const dl = $("#lab-figures");
  dl.replaceChildren();
  $("#lab-rivals").replaceChildren();
  const described = `${r.file}: ${r.format.rows} rows (${r.format.columns_used.join(", ")})`;
  if (kind === "decay") {
    const best = r.models.find((m) => m.model === r.preferred) ?? r.models[0];
    $("#lab-heading").textContent = `${described}: ${r.points} ${r.omega_source === "turning_points" ? "turning points" : "amplitudes"}; the preferred damping law is ${r.preferred ?? "none"}`;
    figureRow(dl, "omega_rad_s", r.omega_rad_s);
    parameters(dl, best.parameters, best.standard_errors);
    qRow(dl, best.q_factor, best.q_factor_standard_error, best.q_factor_lower_bound);
    if (r.gravity) figureRow(dl, "g_m_s2", r.gravity.g_m_s2, r.gravity.standard_error_m_s2);
    rivals(r.models, r.preferred);
  } else if (kind === "trajectory") {
    $("#lab-heading").textContent = `${described}: ${r.points} points, ${r.model} model, ${r.damping_law} damping`;
    parameters(dl, r.parameters, r.standard_errors);
    qRow(dl, r.q_factor, r.q_factor_standard_error, r.q_factor_lower_bound);
    figureRow(dl, "length_m", r.length_m);
  } else {
    $("#lab-heading").textContent = `${described}: ${r.rows} periods against ${r.against}`;
    parameters(dl, r.parameters, r.standard_errors);
    figureRow(dl, "residual_rms_s", r.residual_rms_s);
  }
  const w = $("#lab-words");
  w.replaceChildren();
  helpers.listed(w, "Warnings", reply.warnings);
  helpers.listed(w, "Read from the file", reply.notes);
  draw();
  $("#lab-json").textContent = JSON.stringify(r, null, 2);
}

/** Draws the last figure at the width its box has (a phone's is narrow). */
function draw() {
  if (!last) return;
  const plot = $("#lab-plot");
  const width = Math.round(Math.max(340, Math.min(960, plot.clientWidth || 960)));
  plot.replaceChildren(drawFigure(last.figure, width));
}

/** Fits `bytes` (a Uint8Array) of a file called `name` with the form's options. */
export function fitBytes(bytes, name) {
  const form = $("#lab-form");
  error(null);
  try {
    const request = labRequest(form, name);
    renderFit(request.fit, fit(request, bytes));
  } catch (e) {
    $("#lab-result").hidden = true;
    error(e instanceof PendulumError ? e.message : String(e));
  }
  // (For tests: a fit answered, or refused.)
  document.body.dataset.fitted = String(++fits);
}

async function fitFile(file) {
  fitBytes(new Uint8Array(await file.arrayBuffer()), file.name);
}

/** Wires the room; `h` gives the page's number helpers and download. */
export function setUpLab(h) {
  helpers = h;
  $("#lab-file").addEventListener("change", (e) => {
    const file = e.target.files[0];
    if (file) fitFile(file).catch((err) => error(String(err)));
  });
  $("#lab-paste-fit").addEventListener("click", () => {
    fitBytes(new TextEncoder().encode($("#lab-paste").value), "pasted table");
  });
  const room = $("#lab");
  room.addEventListener("dragover", (e) => { e.preventDefault(); room.classList.add("dragging"); });
  room.addEventListener("dragleave", () => room.classList.remove("dragging"));
  room.addEventListener("drop", (e) => {
    e.preventDefault();
    room.classList.remove("dragging");
    const file = e.dataTransfer?.files?.[0];
    if (file) fitFile(file).catch((err) => error(String(err)));
  });
  $("#lab-form").elements.fit.addEventListener("change", (e) => {
    for (const l of room.querySelectorAll(".track-only")) l.hidden = e.target.value === "period";
  });
  window.addEventListener("resize", draw);
  $("#lab-save-svg").addEventListener("click", () => {
    const svg = $("#lab-plot svg");
    if (!svg) return;
    const text = '<?xml version="1.0" encoding="UTF-8"?>\n' + new XMLSerializer().serializeToString(svg);
    helpers.download(new Blob([text], { type: "image/svg+xml" }), "fit.svg");
  });
  $("#lab-save-csv").addEventListener("click", () => {
    if (last) helpers.download(new Blob([figureCsv(last.figure)], { type: "text/csv" }), "fit.csv");
  });
}
