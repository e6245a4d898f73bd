// The scope (uPlot, pinned in harness/lab/package.json): four channels, each any
// signal of any axis: the plant's columns (its rows, per tick), the servo's watched
// words (their changes, per tick: a target is a step at the tick it changed) and the
// DAC code. History, a trigger with pre-trigger, two cursors, zoom and pan, Freeze,
// CSV and PNG, and a saved run's trace file overlaid. Fed by lab.js (scopeTake).
"use strict";

const CHANNEL_COLORS = ["#58a6ff", "#f0883e", "#3fb950", "#e3b341"];
const STEP_SIGNALS = new Set(["plant:dac", "plant:counter", "plant:contact", "plant:missed"]);
const SCALE_OF = {                  // signals in the same unit share a y scale
  "plant:pos": "counts", "plant:counter": "counts", "word:Desire.Pos": "counts",
  "plant:vel": "counts/s", "plant:vcmd": "counts/s",
};
const scope = {
  channels: [["plant:counter", 0], ["word:Desire.Pos", 0], ["plant:vel", 0], ["plant:dac", 0]],
  words: [],                        // [time_s, {name: value}] where the words changed
  window: 2, frozen: null, pan: 0, zoom: null,
  trigger: "off", level: 0, pre: 0.25, triggeredAt: null,
  cursors: [null, null], overlay: null, rate: null, decimated: null, thinned: 1,
  plot: null, data: null, paces: [],
};
lab.scope = scope;

// ---- what comes in ------------------------------------------------------------------
function scopeTake(m) {             // lab.js's takeData, with each data frame
  for (const tick of m.ticks || []) scope.words.push(tick);
  const cutoff = lab.status.time - KEEP_S;
  let drop = 0;                     // keep the last change before the cutoff: the value there
  while (drop + 1 < scope.words.length && scope.words[drop + 1][0] < cutoff) drop++;
  if (drop) scope.words.splice(0, drop);
  const now = performance.now();    // simulated time against the wall, over 2 s
  scope.paces.push([now, lab.status.time]);
  while (scope.paces.length > 2 && now - scope.paces[0][0] > 2000) scope.paces.shift();
  const [w0, s0] = scope.paces[0];
  scope.rate = now - w0 > 300 && lab.status.state !== "pause" ? (lab.status.time - s0) / ((now - w0) / 1000) : null;
}

function signals() {                // [id, label]: the plant's columns, then the watched words
  const plant = Object.keys(ROW).filter((c) => c !== "time_s" && c !== "axis").map((c) => [`plant:${c}`, c]);
  const words = lab.perAxis.concat(lab.single).map((n) => [`word:${n}`, n]);
  return plant.concat(words);
}

function channelName([id, axis]) {
  const [, name] = id.split(":");
  return lab.single.includes(name) || ["grip", "contact", "missed"].includes(name) ? name : `${AXES[axis]} ${name}`;
}

// The index of the first row at or after time t (rows in time order): a window
// is found without reading the 40 s kept before it, every frame.
function firstFrom(rows, t) {
  let lo = 0, hi = rows.length;
  while (lo < hi) {
    const mid = (lo + hi) >> 1;
    if (rows[mid][ROW.time_s] < t) lo = mid + 1; else hi = mid;
  }
  return lo;
}

// Samples [t, v] of one signal: from `source` (live or frozen): {traces, words}
function samples(source, [id, axis], start, end) {
  const [kind, name] = id.split(":"), out = [];
  if (kind === "plant") {
    const rows = source.traces[axis] || [], column = ROW[name];
    for (let k = firstFrom(rows, start); k < rows.length && rows[k][ROW.time_s] <= end; k++)
      out.push([rows[k][ROW.time_s], rows[k][column]]);
    return out;
  }
  const value = (w) => { const v = w[name]; return v === undefined ? null : Array.isArray(v) ? v[axis] : v; };
  let held = null;
  for (const [t, w] of source.words) {
    if (t < start) { held = value(w); continue; }
    if (t > end) break;
    out.push([t, value(w)]);
  }
  if (held !== null) out.unshift([start, held]);        // the value the window opens with
  if (out.length) out.push([end, out[out.length - 1][1]]);   // and holds to its end
  return out;
}
const isStep = (id) => id.startsWith("word:") || STEP_SIGNALS.has(id);

// ---- the trigger: the last event in what is kept, and the window around it -----------
function triggerTime(source, end) {
  const channel = scope.channels[0];
  if (scope.trigger === "move") {   // a move's start: Desire.Pos of CH1's axis changes
    const s = samples(source, ["word:Desire.Pos", channel[1]], end - KEEP_S, end);
    for (let k = s.length - 2; k > 0; k--) if (s[k][1] !== s[k - 1][1]) return s[k][0];
    return null;
  }
  if (scope.trigger === "rise" || scope.trigger === "fall") {
    const s = samples(source, channel, end - KEEP_S, end), L = scope.level;
    for (let k = s.length - 1; k > 0; k--) {
      const a = s[k - 1][1], b = s[k][1];
      if (a === null || b === null) continue;
      if (scope.trigger === "rise" ? a < L && b >= L : a > L && b <= L) return s[k][0];
    }
  }
  return null;
}

function view() {                   // the source and the time window shown
  const source = scope.frozen || { traces: lab.traces, words: scope.words, end: lab.status.time };
  if (scope.zoom) return { source, start: scope.zoom[0], end: scope.zoom[1] };
  let end = source.end + scope.pan;
  scope.triggeredAt = scope.trigger === "off" ? null : triggerTime(source, source.end);
  if (scope.triggeredAt !== null) end = Math.min(source.end, scope.triggeredAt + (1 - scope.pre) * scope.window) + scope.pan;
  return { source, start: end - scope.window, end };
}

// ---- the overlay: a saved run's plant trace (python -m harness run: NAME.trace.csv) --
scope.loadOverlay = (text, name) => {
  const lines = text.trim().split(/\r?\n/), columns = Object.keys(ROW);
  if (lines[0].split(",").map((c) => c.trim()).join(",") !== columns.join(","))
    throw new Error(`${name}: not a plant trace (its first line must be ${columns.join(",")})`);
  const traces = AXES.map(() => []);
  lines.slice(1).forEach((line, k) => {
    const f = line.split(",");
    const row = f.map((v, i) => (i === ROW.axis ? AXES.indexOf(v) : Number(v)));
    if (f.length !== columns.length || row[ROW.axis] < 0 || row.some(Number.isNaN))
      throw new Error(`${name} line ${k + 2}: not a plant trace row: ${line.slice(0, 60)}`);
    traces[row[ROW.axis]].push(row);
  });
  for (const rows of traces) rows.sort((a, b) => a[ROW.time_s] - b[ROW.time_s]);   // firstFrom
  scope.overlay = { name, traces, words: [] };
  rebuildPlot();
};

function overlayShift(start) {       // the saved run placed where the live one is compared:
  const [id, axis] = scope.channels[0], rows = scope.overlay.traces[axis];   // at the same
  if (!rows.length) return 0;        // CH1 crossing when triggered on one, else from its start
  let at = null;
  if (scope.triggeredAt !== null && (scope.trigger === "rise" || scope.trigger === "fall") && id.startsWith("plant:")) {
    const col = ROW[id.split(":")[1]], L = scope.level;
    at = rows.find((r, k) => k && (scope.trigger === "rise"
      ? rows[k - 1][col] < L && r[col] >= L : rows[k - 1][col] > L && r[col] <= L));
  }
  return at ? scope.triggeredAt - at[ROW.time_s] : start - rows[0][ROW.time_s];
}

// ---- the data uPlot draws: aligned, and min/max per pixel column when denser --------
function series() {                 // [channel, source kind] per drawn series
  const live = scope.channels.map((c, i) => ({ channel: c, i, saved: false }));
  const saved = scope.overlay ? scope.channels.map((c, i) => ({ channel: c, i, saved: true }))
    .filter((s) => s.channel[0].startsWith("plant:")) : [];
  return live.concat(saved);
}

function build(columns) {
  const { source, start, end } = view();
  const shift = scope.overlay ? overlayShift(start) : 0;
  const lists = series().map((s) => (s.saved
    ? samples(scope.overlay, s.channel, start - shift, end - shift).map(([t, v]) => [t + shift, v])
    : samples(source, s.channel, start, end)));
  const steps = series().map((s) => isStep(s.channel[0]));
  const times = new Set();
  for (const list of lists) for (const [t] of list) times.add(t);
  const rows = lists.reduce((n, l) => Math.max(n, l.length), 0);
  scope.thinned = thinning(source, start, end);
  if (columns && times.size > 2 * columns) {          // honest decimation: each pixel's extremes
    scope.decimated = { rows, columns };
    const dt = (end - start) / columns, x = [];
    for (let c = 0; c < columns; c++) x.push(start + (c + 0.25) * dt, start + (c + 0.75) * dt);
    const ys = lists.map((list, k) => {
      const lo = new Array(columns).fill(null), hi = new Array(columns).fill(null);
      const last = new Array(columns).fill(null);
      for (const [t, v] of list) {
        if (v === null) continue;
        const c = Math.min(columns - 1, Math.max(0, Math.floor((t - start) / dt)));
        lo[c] = lo[c] === null ? v : Math.min(lo[c], v);
        hi[c] = hi[c] === null ? v : Math.max(hi[c], v);
        last[c] = v;
      }
      const y = [];
      let held = null;                 // a step signal holds its value through empty columns
      for (let c = 0; c < columns; c++) {
        if (lo[c] === null && steps[k]) { lo[c] = hi[c] = held; }
        y.push(lo[c], hi[c]);
        if (last[c] !== null) held = last[c];
      }
      return y;
    });
    return { x, ys, start, end };
  }
  scope.decimated = null;
  const x = [...times].sort((a, b) => a - b), index = new Map(x.map((t, i) => [t, i]));
  const ys = lists.map((list, k) => {
    const y = new Array(x.length).fill(null);
    for (const [t, v] of list) y[index.get(t)] = v;
    if (steps[k]) for (let i = 1; i < y.length; i++) if (y[i] === null) y[i] = y[i - 1];
    return y;
  });
  return { x, ys, start, end };
}

function valueAt(list, t) {          // the last sample at or before t
  let v = null;
  for (const [s, w] of list) { if (s > t) break; v = w; }
  return v;
}

function thinning(source, start, end) {   // 1 tick in k: the server's thinning at full speed
  const all = source.traces[scope.channels[0][1]] || [];
  const rows = all.slice(firstFrom(all, start), firstFrom(all, end + 1e-9));
  if (rows.length < 3) return 1;
  const gaps = rows.slice(1).map((r, k) => r[ROW.time_s] - rows[k][ROW.time_s]).sort((a, b) => a - b);
  return Math.max(1, Math.round(gaps[gaps.length >> 1] * 60));
}

// ---- the plot ---------------------------------------------------------------------------
const plotBox = document.getElementById("scope-plot");
let scopeShown = null;               // the frozen view the plot has drawn (drawScope)

function rebuildPlot() {
  if (scope.plot) scope.plot.destroy();
  scopeShown = null;
  const scales = [], colors = [];    // each scale's axis in its first channel's colour
  const list = series().map((s) => {
    const id = s.channel[0], scale = SCALE_OF[id] || id;
    if (!scales.includes(scale)) { scales.push(scale); colors.push(CHANNEL_COLORS[s.i]); }
    return {
      label: (s.saved ? "saved " : "") + channelName(s.channel), scale, spanGaps: true,
      stroke: CHANNEL_COLORS[s.i], width: s.saved ? 1.5 : 2, dash: s.saved ? [6, 4] : undefined,
      alpha: s.saved ? 0.7 : 1, paths: isStep(id) ? uPlot.paths.stepped({ align: 1 }) : undefined,
      points: { show: false },
    };
  });
  const fs = Math.min(lab.fontScale || 1, innerWidth <= 1500 ? 1.2 : 1.45);   // --ps (lab-teach.css)
  const axisStyle = { stroke: "#8b949e", grid: { stroke: "#263040", width: 1 }, ticks: { stroke: "#30363d" },
    font: `${Math.round(12 * fs)}px "DejaVu Sans", sans-serif` };
  const axes = [{ ...axisStyle, values: (u, v) => v.map((t) => `${t.toFixed(2)} s`) }].concat(
    scales.map((scale, k) => ({ ...axisStyle, scale, show: k < 2, stroke: colors[k], side: k ? 1 : 3, size: Math.round(56 * fs),
      grid: { ...axisStyle.grid, show: k === 0 } })));
  const r = plotBox.getBoundingClientRect();
  scope.plot = new uPlot({
    width: Math.max(100, r.width), height: Math.max(60, r.height),
    legend: { show: false }, series: [{}].concat(list), axes,
    scales: Object.fromEntries([["x", { time: false }]].concat(
      scales.map((s, k) => [s, scaleOf(k, Math.max(0, scales.length - 2))]))),
    cursor: { drag: { x: true, y: false, setScale: false }, points: { show: false } },
    hooks: {
      setSelect: [(u) => {           // a dragged span: zoom to it (the view holds still)
        if (u.select.width < 4) return;
        const a = u.posToVal(u.select.left, "x"), b = u.posToVal(u.select.left + u.select.width, "x");
        freeze(true);
        scope.zoom = [a, b];
        u.setSelect({ left: 0, width: 0, top: 0, height: 0 }, false);
        lab.dirty = true;
      }],
      draw: [drawCursors],
    },
  }, [[]].concat(list.map(() => [])), plotBox);
  scope.plot.over.addEventListener("click", (e) => {    // a click places cursor A, then B
    const t = scope.plot.posToVal(e.offsetX, "x");
    scope.setCursors(...(scope.cursors[0] === null || scope.cursors[1] !== null ? [t, null] : [scope.cursors[0], t]));
  });
  lab.dirty = true;
}

// The first two scales have an axis. A third or fourth, read with the cursors, gets
// a lane of its own, a quarter of the height from the top down, as a scope's channel
// has its own position, and the first two keep the height below the lanes: the
// hunting servo's DAC code swings full scale at every tick, and drawn over the
// counter and Desire.Pos its band hid them.
const LANE = 0.25, LANE_MARGIN = 0.02;
function scaleOf(k, lanes) {
  if (k < 2) {
    if (!lanes) return { auto: true };
    const below = 1 - LANE * lanes;         // uPlot's own fit (10 % padding), stretched up
    return { auto: true, range: (u, low, high) => {
      const [min, max] = uPlot.rangeNum(low ?? 0, high ?? 1, 0.1, true);
      return [min, min + (max - min) / below];
    } };
  }
  const top = 1 - LANE * (k - 2), bottom = top - LANE;      // fractions of the height
  return { auto: true, range: (u, low, high) => {
    const lo = low ?? 0, hi = high ?? 1, span = (hi - lo || 1) / (LANE - 2 * LANE_MARGIN);
    const min = (hi === lo ? lo - 0.5 : lo) - (bottom + LANE_MARGIN) * span;
    return [min, min + span];
  } };
}

function drawCursors(u) {
  const g = u.ctx;
  scope.cursors.forEach((t, k) => {
    if (t === null) return;
    const X = u.valToPos(t, "x", true);
    g.save(); g.strokeStyle = "#f0f6fc"; g.setLineDash(k ? [4, 4] : []); g.lineWidth = 1.5;
    g.beginPath(); g.moveTo(X, u.bbox.top); g.lineTo(X, u.bbox.top + u.bbox.height); g.stroke();
    g.fillStyle = "#f0f6fc"; g.font = "bold 13px sans-serif"; g.fillText(k ? "B" : "A", X + 4, u.bbox.top + 14);
    g.restore();
  });
  if (scope.triggeredAt !== null && !scope.zoom) {       // the trigger's instant
    const X = u.valToPos(scope.triggeredAt, "x", true);
    g.save(); g.fillStyle = "#ff7b72"; g.beginPath();
    g.moveTo(X - 6, u.bbox.top); g.lineTo(X + 6, u.bbox.top); g.lineTo(X, u.bbox.top + 9); g.fill(); g.restore();
  }
  if (scope.frozen) { g.save(); g.fillStyle = "#ff5c5c"; g.font = "bold 14px sans-serif"; g.textAlign = "right";
    g.fillText("FROZEN", u.bbox.left + u.bbox.width - 6, u.bbox.top + 16); g.restore(); }
}

scope.setCursors = (a, b) => { scope.cursors = [a, b]; lab.dirty = true; };
scope.readout = () => {              // Δt and each channel's Δvalue between the cursors
  const [a, b] = scope.cursors;
  if (a === null) return "click the plot: cursor A, then B";
  const { source } = view(), parts = [`A ${a.toFixed(4)} s`];
  if (b !== null) parts.push(`B ${b.toFixed(4)} s`, `\u0394t ${(b - a).toFixed(4)} s`);
  scope.channels.forEach((c, i) => {
    const s = samples(source, c, Math.min(a, b ?? a) - KEEP_S, Math.max(a, b ?? a) + 1);
    const va = valueAt(s, a), vb = b === null ? null : valueAt(s, b);
    if (va === null) return;
    parts.push(`CH${i + 1} ${round(va)}` + (vb === null ? "" : ` \u2192 ${round(vb)} (\u0394 ${round(vb - va)})`));
  });
  return parts.join(" \u00b7 ");
};
const round = (v) => (Number.isInteger(v) ? String(v) : v.toFixed(3));

function note() {                    // what the page shows against what happened
  const parts = [];
  if (scope.rate !== null) parts.push(`simulated time runs \u00d7${scope.rate < 10 ? scope.rate.toFixed(2) : scope.rate.toFixed(0)} the wall clock`);
  if (scope.thinned > 1) parts.push(`the server sent 1 tick in ${scope.thinned}`);
  if (scope.decimated) parts.push(`min/max of ${scope.decimated.rows} rows per ${scope.decimated.columns} pixel columns`);
  if (scope.trigger !== "off" && scope.triggeredAt === null) parts.push("waiting for the trigger");
  if (scope.overlay) parts.push(`dashed: ${scope.overlay.name}`);
  return parts.join(" \u00b7 ");
}

function drawScope() {               // lab.js's frame loop, when something changed
  if (!scope.plot) rebuildPlot();
  const r = plotBox.getBoundingClientRect();
  const u = scope.plot;
  // Frozen, the picture changes only with the view (the run's data goes on coming):
  // it is not built and drawn again until the view changes.
  const frozen = scope.frozen && JSON.stringify([scope.frozen.end, scope.zoom, scope.pan, scope.window,
    scope.trigger, scope.level, scope.pre, scope.cursors, scope.channels, scope.overlay && scope.overlay.name,
    r.width, r.height, window.devicePixelRatio]);
  if (!frozen || frozen !== scopeShown) {
    scopeShown = frozen;
    if (Math.abs(u.width - r.width) > 1 || Math.abs(u.height - r.height) > 1)
      u.setSize({ width: Math.max(100, r.width), height: Math.max(60, r.height) });
    const { x, ys, start, end } = build(Math.round(u.bbox.width / (window.devicePixelRatio || 1)));
    scope.data = [x].concat(ys);
    scope.view = [start, end];
    u.batch(() => {
      u.setData(scope.data);             // each y scale fitted to what is shown now,
      u.setScale("x", { min: start, max: end });   // the time axis to the window
    });
  }
  // each written only when it changed (put, lab.js): the note's rate changes with
  // every frame, the cursors' readout only when they move
  const line = scope.readout(), box = document.getElementById("scope-readout");
  put(box, line);
  putAttribute(box, "title", line);        // the whole line on hover where it is cut
  put(document.getElementById("scope-note"), note());
}

// ---- CSV and PNG -------------------------------------------------------------------------
scope.csv = () => {                  // the window's samples, undecimated, step values held
  const { x, ys } = build(null);
  const names = series().map((s) => (s.saved ? "saved " : "") + channelName(s.channel));
  return ["time_s"].concat(names).join(",") + "\n" +
    x.map((t, i) => [t.toFixed(9)].concat(ys.map((y) => (y[i] === null ? "" : y[i]))).join(",")).join("\n") + "\n";
};
function download(name, url) {
  const a = document.createElement("a");
  a.href = url; a.download = name; document.body.appendChild(a); a.click(); a.remove();
}
document.getElementById("csv").addEventListener("click", () =>
  download(`scope-${lab.status.time.toFixed(3)}s.csv`, URL.createObjectURL(new Blob([scope.csv()], { type: "text/csv" }))));
document.getElementById("png").addEventListener("click", () =>
  download(`scope-${lab.status.time.toFixed(3)}s.png`, scope.plot.ctx.canvas.toDataURL("image/png")));

// ---- the controls ------------------------------------------------------------------------
function freeze(on) {
  scope.frozen = on ? { traces: lab.traces.map((t) => t.slice()), words: scope.words.slice(), end: lab.status.time } : null;
  if (!on) { scope.zoom = null; scope.pan = 0; }
  const b = document.getElementById("freeze");
  b.classList.toggle("on", on);
  b.setAttribute("aria-pressed", String(on));
  lab.dirty = true;
}
document.getElementById("freeze").addEventListener("click", () => freeze(!scope.frozen));
function panBy(fraction) {           // half a window back or on; the live view freezes first
  if (!scope.frozen) freeze(true);
  const w = scope.zoom ? scope.zoom[1] - scope.zoom[0] : scope.window;
  if (scope.zoom) scope.zoom = scope.zoom.map((t) => t + fraction * w);
  else scope.pan += fraction * w;
  lab.dirty = true;
}
document.getElementById("pan-back").addEventListener("click", () => panBy(-0.5));
document.getElementById("pan-on").addEventListener("click", () => panBy(0.5));
plotBox.addEventListener("wheel", (e) => {   // the timebase: wheel zooms time
  e.preventDefault();
  const f = e.deltaY > 0 ? 1.25 : 0.8;
  if (scope.zoom) {
    const [a, b] = scope.zoom, mid = scope.plot.posToVal(e.offsetX, "x");
    scope.zoom = [mid - (mid - a) * f, mid + (b - mid) * f];
  } else scope.window = Math.min(KEEP_S - 5, Math.max(0.1, scope.window * f));
  document.getElementById("scope-window").value = "";
  lab.dirty = true;
}, { passive: false });

function fillChannels() {            // the channel pickers, once the hello named the signals
  const box = document.getElementById("scope-channels");
  const options = signals().map(([id, label]) => `<option value="${id}">${label}</option>`).join("");
  const axes = AXES.map((a, i) => `<option value="${i}">${a}</option>`).join("");
  box.innerHTML = scope.channels.map((c, i) =>
    `<span class="channel" style="border-color:${CHANNEL_COLORS[i]}"><b style="color:${CHANNEL_COLORS[i]}">CH${i + 1}</b>` +
    `<select data-ch="${i}" data-part="0" aria-label="channel ${i + 1}: signal">${options}</select>` +
    `<select data-ch="${i}" data-part="1" aria-label="channel ${i + 1}: axis">${axes}</select></span>`).join("");
  box.querySelectorAll("select").forEach((s) => {
    s.value = String(scope.channels[s.dataset.ch][s.dataset.part]);
    s.addEventListener("change", () => {
      scope.channels[s.dataset.ch][s.dataset.part] = s.dataset.part === "1" ? Number(s.value) : s.value;
      rebuildPlot();
    });
  });
  rebuildPlot();
}
scope.setChannel = (i, id, axis) => { scope.channels[i] = [id, axis]; fillChannels(); };
const byId = (id) => document.getElementById(id);
byId("scope-window").addEventListener("change", (e) => {
  if (e.target.value) { scope.window = Number(e.target.value); scope.zoom = null; }
  lab.dirty = true;
});
byId("scope-trigger").addEventListener("change", (e) => { scope.trigger = e.target.value; lab.dirty = true; });
byId("scope-level").addEventListener("change", (e) => { scope.level = Number(e.target.value) || 0; lab.dirty = true; });
byId("scope-pre").addEventListener("change", (e) => { scope.pre = Number(e.target.value); lab.dirty = true; });
byId("scope-overlay").addEventListener("change", async (e) => {
  const file = e.target.files[0];
  if (!file) return;
  try { scope.loadOverlay(await file.text(), file.name); } catch (err) { lab.errors.push(err.message); byId("scope-note").textContent = err.message; }
});
window.addEventListener("resize", () => { lab.dirty = true; scope.restyle(); });   // the text cap (--ps)
scope.start = fillChannels;          // lab.js, after the hello
scope.restyle = () => { if (scope.plot) rebuildPlot(); };   // lab-teach.js: a new text size
