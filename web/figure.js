// Draws a figure as the library builds it (pendulum_data::figure: panels
// of named series, models as lines and data as dots, with titles, axis
// labels in units and scales) into SVG, by the command line's --plot
// conventions: its palette (Okabe–Ito, in its order), the preferred model
// wide and its rivals thin, data drawn over models, log axes where the
// figure asks for them, ticks at round numbers, a legend per panel.

const NS = "http://www.w3.org/2000/svg";
const PALETTE = ["#0072b2", "#d55e00", "#009e73", "#cc79a7", "#56b4e9", "#e69f00", "#f0e442", "#5a5a5a"];
const WIDTHS = { normal: 2, strong: 4, light: 1 };

function el(name, attrs = {}, text) {
  const e = document.createElementNS(NS, name);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, String(v));
  if (text !== undefined) e.textContent = text;
  return e;
}

/** A value in axis units (its log10 on a log axis), or null if not shown. */
function toAxis(scale, v) {
  if (typeof v !== "number" || !Number.isFinite(v)) return null;
  if (scale === "log") return v > 0 ? Math.log10(v) : null;
  return v;
}

/** Round ticks over [lo, hi] in axis units. */
function ticks(scale, lo, hi) {
  if (scale === "log") {
    const out = [];
    for (let e = Math.ceil(lo); e <= Math.floor(hi); e++) out.push(e);
    if (out.length >= 2) return out.map((u) => [u, 10 ** u]);
    // Less than two decades' marks: linear ticks of the values.
    return ticks("linear", 10 ** lo, 10 ** hi).map(([, v]) => [Math.log10(v), v]).filter(([u]) => u >= lo && u <= hi);
  }
  const span = hi - lo || Math.abs(hi) || 1;
  const raw = span / 6;
  const mag = 10 ** Math.floor(Math.log10(raw));
  const step = [1, 2, 2.5, 5, 10].map((m) => m * mag).find((s) => s >= raw) ?? raw;
  const out = [];
  for (let v = Math.ceil(lo / step) * step; v <= hi + step * 1e-9; v += step) out.push([v, Math.abs(v) < step * 1e-9 ? 0 : v]);
  return out;
}

/** A tick's label: no more digits than the step needs. */
function tickLabel(v, scale) {
  if (v === 0) return "0";
  const a = Math.abs(v);
  if (a >= 1e5 || a < 1e-3) return v.toExponential(scale === "log" ? 0 : 1).replace("e+", "e");
  return String(Number(v.toPrecision(6)));
}

/** The span of the panel's values in axis units, padded 4%. */
function span(panel, axis) {
  const scale = axis === 0 ? panel.x_scale : panel.y_scale;
  let lo = Infinity;
  let hi = -Infinity;
  for (const s of panel.series) {
    s.points.forEach((p, i) => {
      const u = toAxis(scale, p[axis]);
      if (u === null || toAxis(axis === 0 ? panel.y_scale : panel.x_scale, p[1 - axis]) === null) return;
      lo = Math.min(lo, u);
      hi = Math.max(hi, u);
      if (axis === 1 && s.bars) {
        for (const b of s.bars[i]) {
          const ub = toAxis(scale, b);
          if (ub !== null) { lo = Math.min(lo, ub); hi = Math.max(hi, ub); }
        }
      }
    });
  }
  if (axis === 0) for (const m of panel.marks) { const u = toAxis(scale, m.x); if (u !== null) { lo = Math.min(lo, u); hi = Math.max(hi, u); } }
  if (!Number.isFinite(lo)) return [0, 1];
  if (hi === lo) { const d = Math.abs(lo) * 0.05 || 0.5; return [lo - d, hi + d]; }
  const pad = (hi - lo) * 0.04;
  return [lo - pad, hi + pad];
}

/** More data points than a law drawn under them can be seen through. */
const DENSE_CLOUD = 400;

/** The legend's lines: the labelled series, then the marks. */
function legendLines(panel) {
  const named = panel.series.map((s, i) => [s, i]).filter(([s]) => s.label);
  if (named.length < 2 && !panel.marks.length) return [];
  return [...named.map(([s, i]) => [s.label, PALETTE[(s.color ?? i) % PALETTE.length], s.style, s.weight]), ...panel.marks.map((m) => [m.label, "#505050", "mark", "normal"])];
}

/** A panel at (x0, y0), `w` by `h` with the plot `plotHeight` high; its
 * legend inside the frame, or below it (`below`, a narrow figure's). */
function drawPanel(svg, panel, x0, y0, w, plotHeight, below, titleFont) {
  const h = plotHeight;
  const left = 78, right = 14, top = 34, bottom = 46;
  const pw = w - left - right, ph = h - top - bottom;
  const [xl, xh] = span(panel, 0);
  const [yl, yh] = span(panel, 1);
  const X = (u) => x0 + left + ((u - xl) / (xh - xl)) * pw;
  const Y = (u) => y0 + top + ph - ((u - yl) / (yh - yl)) * ph;
  const g = el("g", { class: "panel" });
  // A title longer than the frame is set smaller (a phone's narrow figure).
  const titleSize = Math.max(10, Math.min(titleFont, pw / (0.66 * panel.title.length)));
  g.append(el("text", { x: x0 + left + pw / 2, y: y0 + 22, "text-anchor": "middle", class: "title", "font-size": titleSize.toFixed(1) }, panel.title));
  g.append(el("rect", { x: x0 + left, y: y0 + top, width: pw, height: ph, fill: "#fff", stroke: "#888" }));
  for (const [u, v] of ticks(panel.x_scale, xl, xh)) {
    g.append(el("line", { x1: X(u), x2: X(u), y1: y0 + top, y2: y0 + top + ph, stroke: "#ebebeb" }));
    g.append(el("text", { x: X(u), y: y0 + top + ph + 16, "text-anchor": "middle", class: "tick" }, tickLabel(v, panel.x_scale)));
  }
  for (const [u, v] of ticks(panel.y_scale, yl, yh)) {
    g.append(el("line", { x1: x0 + left, x2: x0 + left + pw, y1: Y(u), y2: Y(u), stroke: "#ebebeb" }));
    g.append(el("text", { x: x0 + left - 6, y: Y(u) + 4, "text-anchor": "end", class: "tick" }, tickLabel(v, panel.y_scale)));
  }
  g.append(el("text", { x: x0 + left + pw / 2, y: y0 + h - 8, "text-anchor": "middle", class: "axis" }, panel.x_label));
  g.append(el("text", { transform: `translate(${x0 + 16},${y0 + top + ph / 2}) rotate(-90)`, "text-anchor": "middle", class: "axis" }, panel.y_label));
  const clipId = `clip-${Math.random().toString(36).slice(2)}`;
  const clip = el("clipPath", { id: clipId });
  clip.append(el("rect", { x: x0 + left, y: y0 + top, width: pw, height: ph }));
  g.append(clip);
  const plot = el("g", { "clip-path": `url(#${clipId})` });
  // Models first, data over them; a cloud of more points than a law can
  // be seen through (DENSE_CLOUD, as the command line's) first, the law
  // over it.
  const dense = panel.series.some((s) => s.style === "dots" && s.points.length > DENSE_CLOUD);
  const last = dense ? "line" : "dots";
  const order = panel.series.map((s, i) => [s, i]).sort((a, b) => (a[0].style === last) - (b[0].style === last));
  for (const [s, i] of order) {
    const color = PALETTE[(s.color ?? i) % PALETTE.length];
    const pts = s.points
      .map((p) => [toAxis(panel.x_scale, p[0]), toAxis(panel.y_scale, p[1])])
      .map(([u, v]) => (u === null || v === null ? null : [X(u), Y(v)]));
    if (s.style === "line") {
      // A break where the curve cannot be shown.
      let run = [];
      const flush = () => {
        if (run.length > 1) plot.append(el("polyline", { points: run.map((p) => p.map((c) => c.toFixed(1)).join(",")).join(" "), fill: "none", stroke: color, "stroke-width": WIDTHS[s.weight] ?? 2, "stroke-linejoin": "round" }));
        run = [];
      };
      for (const p of pts) { if (p) run.push(p); else flush(); }
      flush();
    } else {
      const r = pts.length > 400 ? 2 : 3;
      pts.forEach((p, k) => {
        if (!p) return;
        if (s.bars) {
          const [lo, hi] = s.bars[k].map((b) => toAxis(panel.y_scale, b));
          if (lo !== null && hi !== null) plot.append(el("line", { x1: p[0], x2: p[0], y1: Y(lo), y2: Y(hi), stroke: color }));
        }
        plot.append(el("circle", { cx: p[0].toFixed(1), cy: p[1].toFixed(1), r, fill: color }));
      });
    }
  }
  for (const m of panel.marks) {
    const u = toAxis(panel.x_scale, m.x);
    if (u !== null) plot.append(el("line", { x1: X(u), x2: X(u), y1: y0 + top, y2: y0 + top + ph, stroke: "#505050", "stroke-dasharray": "6 4" }));
  }
  g.append(plot);
  // The legend: top right inside the frame, or under the axis label.
  const lines = legendLines(panel);
  if (lines.length) {
    const lw = below ? w - left - right : Math.min(pw * 0.6, 14 + 7 * Math.max(...lines.map((l) => l[0].length)));
    const lx = below ? x0 + left : x0 + left + pw - lw - 8;
    const ly = below ? y0 + h : y0 + top + 8;
    const box = el("g", { class: "legend" });
    box.append(el("rect", { x: lx, y: ly, width: lw, height: 18 * lines.length + 8, fill: "#fff", "fill-opacity": 0.85, stroke: "#969696" }));
    lines.forEach(([label, color, style, weight], k) => {
      const yy = ly + 16 + 18 * k;
      if (style === "dots") box.append(el("circle", { cx: lx + 14, cy: yy - 4, r: 3, fill: color }));
      else box.append(el("line", { x1: lx + 6, x2: lx + 24, y1: yy - 4, y2: yy - 4, stroke: color, "stroke-width": WIDTHS[weight] ?? 2, ...(style === "mark" ? { "stroke-dasharray": "4 3" } : {}) }));
      box.append(el("text", { x: lx + 30, y: yy, class: "legend-text" }, label));
    });
    g.append(box);
  }
  svg.append(g);
}

/** The figure as an SVG element, `width` CSS pixels wide. */
export function drawFigure(figure, width = 960) {
  const narrow = width < 600;
  const plotHeight = narrow ? 250 : 320;
  // A narrow figure's legends go under their panels, each its own height.
  const heights = figure.panels.map((p) => plotHeight + (narrow && legendLines(p).length ? 18 * legendLines(p).length + 16 : 0));
  const height = heights.reduce((a, b) => a + b, 0);
  const svg = el("svg", { xmlns: NS, viewBox: `0 0 ${width} ${height}`, width, height, role: "img", class: "figure" });
  const title = narrow ? 13 : 16;
  svg.append(el("style", {}, `text{font-family:'DejaVu Sans',system-ui,sans-serif;fill:#1d2430}.title{font-weight:600}.axis{font-size:14px}.tick{font-size:12px;fill:#444}.legend-text{font-size:12px}`));
  svg.append(el("rect", { x: 0, y: 0, width, height, fill: "#fff" }));
  let y = 0;
  figure.panels.forEach((p, i) => {
    drawPanel(svg, p, 0, y, width, plotHeight, narrow, title);
    y += heights[i];
  });
  svg.setAttribute("aria-label", figure.panels.map((p) => `${p.title}: ${p.y_label} against ${p.x_label}`).join("; "));
  // (For tests: the data points, and all points with both coordinates.)
  const finite = (p) => Number.isFinite(p[0]) && Number.isFinite(p[1]);
  const all = figure.panels.flatMap((p) => p.series);
  svg.dataset.dots = String(all.filter((s) => s.style === "dots").reduce((n, s) => n + s.points.filter(finite).length, 0));
  svg.dataset.points = String(all.reduce((n, s) => n + s.points.filter(finite).length, 0));
  return svg;
}

/** The figure's points as CSV: one row a point, its panel, series and axes named. */
export function figureCsv(figure) {
  const q = (t) => `"${String(t).replaceAll('"', '""')}"`;
  const rows = ["panel,series,x_label,x,y_label,y"];
  for (const p of figure.panels) {
    for (const s of p.series) {
      for (const [x, y] of s.points) {
        if (x === null || y === null) continue;
        rows.push([q(p.title), q(s.label), q(p.x_label), x, q(p.y_label), y].join(","));
      }
    }
  }
  return rows.join("\n") + "\n";
}
