// The lab bench page: a terminal, the robot, a scope and the servo's words,
// all fed by one websocket (harness/lab/server.py). The page only observes the
// machine, except for what the user types and the time controls.
"use strict";

const COLORS = ["#58a6ff", "#3fb950", "#d29922", "#bc8cff"];
// What the plant is, from the server's hello (build/pdp11's SHOW PLANT LAYOUT,
// harness/machine/plant_rows.py): its axes, their units, the row's columns.
let AXES = [], UNITS = [], COUNTS_PER_UNIT = [], ROW = {};
const KEEP_S = 40;                 // seconds of trace kept per axis (the widest window + margin)
const GAP_S = 1 / 30;              // further apart than this: ticks the fast run did not report

// ---- the connection ----------------------------------------------------------------
const params = new URLSearchParams(location.search);
const token = params.get("token") || sessionStorage.getItem("labToken");
if (params.get("token")) {          // off the address bar (and the projector), kept for reloads
  sessionStorage.setItem("labToken", token);
  history.replaceState(null, "", location.pathname);
}
const socket = new WebSocket(`ws://${location.host}/ws?token=${encodeURIComponent(token || "")}`);
const send = (message) => socket.readyState === 1 && socket.send(JSON.stringify(message));
// The messages both ways are harness/lab/protocol.py's (tests check these against it).

const lab = {                      // everything the page knows; window.lab for tests
  stops: {}, status: { time: 0, tick: 0, state: "run", speed: "real", power: "off" },
  servo: {}, perAxis: [], single: [], traces: [], latest: [],
  rowsSeen: 0, frozenAt: null, axis: 0, window: 2, ended: false, connected: false, dirty: true,
  keyboard: { holder: null, you: false }, outbox: "", room: 4096, errors: [],
};
window.lab = lab;

// ---- the terminal --------------------------------------------------------------------
const term = new Terminal({
  fontFamily: '"DejaVu Sans Mono", monospace', fontSize: 17, cursorBlink: true,
  scrollback: 5000, theme: { background: "#000000", foreground: "#e6edf3", cursor: "#f0883e" },
});
const fit = new FitAddon.FitAddon();
term.loadAddon(fit);
term.open(document.getElementById("terminal"));
function fitTerminal() {           // the largest font that shows the FORTH's 80 columns
  for (let size = 19; size >= 12; size--) {
    term.options.fontSize = size;
    const dims = fit.proposeDimensions();
    if (dims && dims.cols >= 80) break;
  }
  fit.fit();
}
fitTerminal();
// Keys: the server holds what the machine has not read yet, within a bounded
// queue; the page sends a paste in pieces (MAX_KEYS, protocol.py) as room is
// reported (an `input` answer to each piece, and every data frame).
const MAX_KEYS = 4096;
function sendKeys() {
  while (lab.outbox && socket.readyState === 1 && lab.keyboard.you) {
    const n = Math.min(MAX_KEYS, lab.room, lab.outbox.length);
    if (n <= 0) break;
    send({ t: "key", d: lab.outbox.slice(0, n) });
    lab.outbox = lab.outbox.slice(n);
    lab.room -= n;
  }
  showInput();
}
lab.type = (d) => {                 // what the terminal gives, and tests
  if (!lab.keyboard.you && lab.keyboard.holder !== null) return;   // watching
  if (lab.keyboard.holder === null) lab.keyboard.you = true;       // the first to type takes it
  // ^C and ^E act at once: they go ahead of a paste not yet sent; ^C drops it
  const urgent = d.search(/[\x03\x05]/);
  if (urgent >= 0) {
    lab.outbox += d.slice(0, urgent);
    if (d[urgent] === "\x03" && lab.outbox) {
      term.write(`\r\n[lab] ^C: ${lab.outbox.length} characters not yet sent by this page were dropped\r\n`);
      lab.outbox = "";
    }
    send({ t: "key", d: d[urgent] });
    lab.type(d.slice(urgent + 1));
    return;
  }
  lab.outbox += d;
  sendKeys();
};
term.onData((d) => { typedAhead.key(d, lab.status); lab.type(d); });   // lab-typed-ahead.js
lab.take = () => send({ t: "take" });
document.getElementById("take").addEventListener("click", () => { lab.take(); term.focus(); });
function showInput() {
  const waiting = (lab.status.waiting || 0) + lab.outbox.length;
  const box = document.getElementById("waiting");
  box.textContent = waiting ? `${waiting} characters waiting for the machine` : "";
  box.hidden = !waiting;
}
function showKeyboard() {
  const k = lab.keyboard, note = document.getElementById("keyboard");
  note.textContent = k.you ? "You hold the keyboard"
    : k.holder ? `Watching: ${k.holder} holds the keyboard` : "Nobody holds the keyboard: type to take it";
  note.className = k.you ? "mine" : "";
  document.getElementById("take").hidden = k.you || !k.holder;
}
term.focus();
lab.screen = () => {               // the terminal's text, for tests
  const b = term.buffer.active, lines = [];
  for (let i = 0; i < b.length; i++) lines.push(b.getLine(i).translateToString(true));
  return lines.join("\n");
};

socket.onopen = () => { lab.connected = true; };
socket.onmessage = (event) => {
  const m = JSON.parse(event.data);
  if (m.t === "con") term.write(m.d);
  else if (m.t === "data") { takeData(m); showInput(); }
  else if (m.t === "history") showHistory(m.rows);   // lab-panel.js
  else if (m.t === "hello") {
    learnPlant(m.plant);
    Object.assign(lab, { stops: m.stops, perAxis: m.per_axis, single: m.single, status: m.status });
    term.write(m.con);
    buildTable();
    takeKeyboard(m.keyboard);
    lab.dirty = true;
  } else if (m.t === "keyboard") takeKeyboard(m);
  else if (m.t === "input") { lab.room = m.room; lab.status.waiting = m.waiting; sendKeys(); }
  else if (m.t === "error") {
    lab.errors.push(m.why);
    term.write(`\r\n\x1b[33m[lab] ${m.why}\x1b[0m\r\n`);
  } else if (m.t === "ended") showEnded(m.safe);
};
function takeKeyboard(k) {
  lab.keyboard = { holder: k.holder, you: k.you };
  if (!k.you) lab.outbox = "";       // what was not sent goes with the keyboard
  showKeyboard();
  sendKeys();
}

socket.onclose = () => { if (!lab.ended) showEnded(null, "the lab server went away"); };

function learnPlant(plant) {
  AXES = plant.axes.split("");
  UNITS = plant.units.map((u) => (u === "deg" ? "\u00b0" : u));
  COUNTS_PER_UNIT = plant.per_unit;
  ROW = Object.fromEntries(plant.columns.map((name, i) => [name, i]));
  lab.traces = AXES.map(() => []);
  lab.latest = AXES.map(() => null);
}

function showEnded(safe, why) {
  lab.ended = true;
  const box = document.getElementById("ended");
  box.textContent = why || (safe ? "Session ended: every block written, disk detached. Bye."
                                 : "Session ended: see the console for what was not saved.");
  box.hidden = false;
  setBadge("ended", "ENDED");
  document.querySelectorAll("header button").forEach((b) => { b.disabled = true; });
}

function takeData(m) {
  lab.dirty = true;
  lab.status = m.status;
  if (m.status.waiting === 0 && !lab.outbox) lab.room = Math.max(lab.room, MAX_KEYS);
  lab.servo = m.servo;
  if (m.panel) lab.panel = m.panel;   // lab-panel.js draws it
  for (const row of m.rows) {
    const trace = lab.traces[row[ROW.axis]];
    trace.push(row);
    lab.latest[row[ROW.axis]] = row;
    lab.rowsSeen++;
  }
  const cutoff = lab.status.time - KEEP_S;
  for (const trace of lab.traces) {
    let drop = 0;
    while (drop < trace.length && trace[drop][ROW.time_s] < cutoff) drop++;
    if (drop) trace.splice(0, drop);
  }
}

// ---- time control ----------------------------------------------------------------------
function setBadge(kind, text) {
  const badge = document.getElementById("state");
  badge.className = "badge " + kind;
  badge.textContent = text;
}
document.querySelectorAll("#speeds button").forEach((b) =>
  b.addEventListener("click", () => send({ t: "speed", v: b.dataset.speed })));
document.getElementById("pause").addEventListener("click", () =>
  send({ t: lab.status.state === "pause" ? "run" : "pause" }));
document.getElementById("step").addEventListener("click", () => send({ t: "step" }));
document.getElementById("power").addEventListener("click", () =>
  send({ t: "power", v: lab.status.power === "on" ? "off" : "on" }));

function drawStatus() {
  const s = lab.status;
  document.getElementById("simtime").textContent = `${s.time.toFixed(3)} s`;
  document.getElementById("simtick").textContent = `tick ${s.tick} \u00b7 60 Hz`;
  if (!lab.ended) {
    const speedText = { real: "\u00d71", x10: "\u00d710", full: "FULL" }[s.speed] || "";
    if (s.prompt) setBadge("pause", "STOPPED sim>");   // SIMH has the machine stopped
    else if (s.state === "pause") setBadge("pause", "PAUSED");
    else setBadge("run", `RUN ${speedText}`);
  }
  document.getElementById("pause").textContent = s.state === "pause" ? "Run" : "Pause";
  const power = document.getElementById("power");
  power.textContent = s.power === "on" ? "Turn amps off" : "Turn amps on";  // what a click does
  power.title = `the amplifier rack is ${s.power.toUpperCase()}: click to switch it ` +
    `${s.power === "on" ? "off" : "on"} (SET PLANT POWER)`;
  power.setAttribute("aria-pressed", String(s.power === "on"));
  power.classList.toggle("on", s.power === "on");
  typedAhead.status(s);
  document.querySelectorAll("#speeds button").forEach((b) =>
    b.classList.toggle("on", b.dataset.speed === s.speed));
}

// ---- canvases ----------------------------------------------------------------------------
function sized(canvas) {
  const ratio = window.devicePixelRatio || 1, r = canvas.getBoundingClientRect();
  const w = Math.max(1, Math.round(r.width * ratio)), h = Math.max(1, Math.round(r.height * ratio));
  if (canvas.width !== w || canvas.height !== h) { canvas.width = w; canvas.height = h; }
  const g = canvas.getContext("2d");
  g.setTransform(ratio, 0, 0, ratio, 0, 0);
  return { g, w: r.width, h: r.height };
}

function stopsOf(axis) {
  const s = lab.stops[AXES[axis]];
  return s ? { min: s[0], max: s[1] } : { min: -9600, max: 9600 };
}

function position(axis) {
  const row = lab.latest[axis];
  return row ? row[ROW.pos] : 0;
}

function atStop(axis) {
  const s = stopsOf(axis), p = position(axis);
  return p <= s.min + 0.5 ? -1 : p >= s.max - 0.5 ? 1 : 0;
}

function goal(axis) {               // Desire.Pos: counts on the axis's counter
  const d = lab.servo["Desire.Pos"];
  return d ? d[axis] : null;
}

function target(axis) {             // the same place on the plant: the counter counts from p0
  const d = goal(axis), row = lab.latest[axis];
  return d === null || !row ? null : row[ROW.pos] - row[ROW.counter] + d;
}

function label(g, text, x, y, color, align = "left", size = 15) {
  g.fillStyle = color;
  g.font = `${size}px "DejaVu Sans", sans-serif`;
  g.textAlign = align;
  g.fillText(text, x, y);
}

function units(axis, counts) {
  return `${(counts / COUNTS_PER_UNIT[axis]).toFixed(3)} ${UNITS[axis]}`;
}

// ---- the robot: lab-robot.js ---------------------------------------------------------

// ---- the scope ---------------------------------------------------------------------------
const STRIPS = [
  { title: "position (counts)", series: [["pos", "plant", "#58a6ff"]] },
  { title: "counter (counts)", series: [["counter", "counter", "#79c0ff"]], target: true },
  { title: "velocity (counts/s)", series: [["vel", "actual", "#3fb950"], ["vcmd", "commanded", "#ff7b72"]] },
  { title: "DAC code", series: [["dac", "code", "#d29922"]], steps: true },
];

function windowRows() {
  const end = lab.frozenAt !== null ? lab.frozenAt : lab.status.time;
  const rows = lab.traces[lab.axis].filter((r) => r[ROW.time_s] >= end - lab.window && r[ROW.time_s] <= end);
  return { rows, end, start: end - lab.window };
}

function drawScope() {
  const { g, w, h } = sized(document.getElementById("scope"));
  g.clearRect(0, 0, w, h);
  const { rows, start, end } = windowRows();
  const left = 78, right = w - 10, stripH = (h - 26) / STRIPS.length;
  const tx = (t) => left + (t - start) / (end - start) * (right - left);
  STRIPS.forEach((strip, i) => {
    const top = i * stripH + 4, bottom = top + stripH - 8;
    const values = [];
    for (const r of rows) for (const [key] of strip.series) values.push(r[ROW[key]]);
    const want = strip.target ? goal(lab.axis) : null;
    if (want !== null) values.push(want);
    let lo = Math.min(...values), hi = Math.max(...values);
    if (!values.length) { lo = -1; hi = 1; }
    if (hi - lo < 4) { lo -= 2; hi += 2; }
    const pad = (hi - lo) * 0.08; lo -= pad; hi += pad;
    const ty = (v) => bottom - (v - lo) / (hi - lo) * (bottom - top);
    g.fillStyle = "#0b1220"; g.fillRect(left, top, right - left, bottom - top);
    drawTicks(g, start, end, tx, top, bottom, i === STRIPS.length - 1);
    g.strokeStyle = "#30363d"; g.lineWidth = 1;
    if (lo < 0 && hi > 0) { g.beginPath(); g.moveTo(left, ty(0)); g.lineTo(right, ty(0)); g.stroke(); }
    if (want !== null) {
      g.setLineDash([8, 6]); g.strokeStyle = "#f0883e"; g.lineWidth = 2;
      g.beginPath(); g.moveTo(left, ty(want)); g.lineTo(right, ty(want)); g.stroke(); g.setLineDash([]);
    }
    for (const [key, , color] of strip.series) {
      g.strokeStyle = color; g.lineWidth = 2; g.beginPath();
      rows.forEach((r, k) => {
        const X = tx(r[ROW.time_s]), Y = ty(r[ROW[key]]);
        if (k === 0 || r[ROW.time_s] - rows[k - 1][ROW.time_s] > GAP_S) g.moveTo(X, Y);  // ticks not reported
        else if (strip.steps || key === "counter") { g.lineTo(X, ty(rows[k - 1][ROW[key]])); g.lineTo(X, Y); }
        else g.lineTo(X, Y);
      });
      g.stroke();
    }
    label(g, hi.toFixed(0), left - 6, top + 12, "#8b949e", "right", 12);
    label(g, lo.toFixed(0), left - 6, bottom, "#8b949e", "right", 12);
    const legend = [[`${AXES[lab.axis]} ${strip.title}`, COLORS[lab.axis], 14]].concat(
      strip.series.concat(want !== null ? [[0, "Desire.Pos", "#f0883e"]] : [])
        .map(([, name, color]) => [`\u2014 ${name}`, color, 13]));
    let lx = left + 8, width = 0;
    for (const [text, , size] of legend) {
      g.font = `${size}px "DejaVu Sans", sans-serif`;
      width += g.measureText(text).width + 14;
    }
    g.fillStyle = "rgba(11, 18, 32, 0.85)";          // the legend stays readable over the traces
    g.fillRect(left + 2, top + 2, width + 6, 21);
    for (const [text, color, size] of legend) {
      label(g, text, lx, top + 17, color, "left", size);
      lx += g.measureText(text).width + 14;
    }
  });
  if (lab.frozenAt !== null) label(g, "FROZEN", right - 8, 20, "#ff5c5c", "right", 15);
}

function drawTicks(g, start, end, tx, top, bottom, withLabels) {
  const span = end - start;
  if (span <= 2.5) {                                // the servo's 60 Hz ticks
    g.strokeStyle = "#1f2a3a"; g.lineWidth = 1;
    for (let n = Math.ceil(start * 60); n <= end * 60; n++) {
      g.beginPath(); g.moveTo(tx(n / 60), top); g.lineTo(tx(n / 60), bottom); g.stroke();
    }
  }
  const step = span <= 1 ? 0.1 : span <= 3 ? 0.5 : span <= 12 ? 2 : 5;
  g.strokeStyle = "#3b4656";
  for (let s = Math.ceil(start / step) * step; s <= end; s += step) {
    g.beginPath(); g.moveTo(tx(s), top); g.lineTo(tx(s), bottom); g.stroke();
    if (withLabels) label(g, `${s.toFixed(step < 1 ? 1 : 0)} s`, tx(s), bottom + 16, "#8b949e", "center", 12);
  }
}

function pick(selector, key, apply) {
  document.querySelectorAll(selector).forEach((b) => b.addEventListener("click", () => {
    apply(b.dataset[key]);
    document.querySelectorAll(selector).forEach((o) => o.classList.toggle("on", o === b));
  }));
}
pick("#axes button", "axis", (v) => { lab.axis = Number(v); });
pick("#windows button", "window", (v) => { lab.window = Number(v); });
document.querySelector('#axes button[data-axis="0"]').classList.add("on");
document.querySelector('#windows button[data-window="2"]').classList.add("on");
document.getElementById("scope").addEventListener("wheel", (e) => {
  e.preventDefault();
  lab.window = Math.min(KEEP_S - 5, Math.max(0.1, lab.window * (e.deltaY > 0 ? 1.25 : 0.8)));
  lab.dirty = true;
  document.querySelectorAll("#windows button").forEach((o) => o.classList.remove("on"));
});
document.getElementById("freeze").addEventListener("click", (e) => {
  lab.frozenAt = lab.frozenAt === null ? lab.status.time : null;
  e.target.classList.toggle("on", lab.frozenAt !== null);
});

function download(name, url) {
  const a = document.createElement("a");
  a.href = url; a.download = name; document.body.appendChild(a); a.click(); a.remove();
}
lab.csv = () => {                                    // the window, every axis, as the plant trace
  const end = lab.frozenAt !== null ? lab.frozenAt : lab.status.time, start = end - lab.window;
  const rows = [].concat(...lab.traces).filter((r) => r[ROW.time_s] >= start && r[ROW.time_s] <= end)
    .sort((a, b) => a[ROW.time_s] - b[ROW.time_s] || a[ROW.axis] - b[ROW.axis]);
  const columns = Object.keys(ROW);
  return columns.join(",") + "\n" + rows.map((r) =>
    columns.map((name) => (CSV_FORMAT[name] || String)(r[ROW[name]])).join(",")).join("\n") + "\n";
};
const CSV_FORMAT = {                                 // as plant_dev.c writes the row
  time_s: (v) => v.toFixed(9), axis: (v) => AXES[v], grip: (v) => v.toFixed(2),
  vcmd: (v) => v.toFixed(3), vel: (v) => v.toFixed(3), pos: (v) => v.toFixed(3),
};
document.getElementById("csv").addEventListener("click", () =>
  download(`scope-${lab.status.time.toFixed(3)}s.csv`, URL.createObjectURL(new Blob([lab.csv()], { type: "text/csv" }))));
document.getElementById("png").addEventListener("click", () =>
  download(`scope-${AXES[lab.axis]}-${lab.status.time.toFixed(3)}s.png`, document.getElementById("scope").toDataURL("image/png")));

// ---- the servo's words ----------------------------------------------------------------------
const STATES = { 0: "Stop", 1: "Move" };
const SHORT = { "Desire.Pos": "Desire.Pos", "Command.Status": "Cmd.Status", "Delay.Left": "Delay.Left" };
function buildTable() {
  const head = document.querySelector("#servo thead");
  head.innerHTML = "<tr><th>axis</th><th>counter</th>" +
    lab.perAxis.map((n) => `<th>${SHORT[n] || n}</th>`).join("") + "</tr>";
}

let tableHtml = "";
function drawTable() {
  const body = document.querySelector("#servo tbody");
  const known = lab.perAxis.filter((n) => n in lab.servo);
  let html = "";
  AXES.forEach((a, i) => {
    const row = lab.latest[i];
    const moving = lab.servo["Command.Status"] && lab.servo["Command.Status"][i];
    html += `<tr><td class="axis" style="color:${COLORS[i]}">${a}</td><td>${row ? row[ROW.counter] : ""}</td>` +
      lab.perAxis.map((n) => {
        let v = lab.servo[n] ? lab.servo[n][i] : "";
        if (n === "State" && v in STATES) v = `${STATES[v]} ${v}`;   // block 1000's CONs
        return `<td${moving && n === "Command.Status" ? ' class="moving"' : ""}>${v}</td>`;
      }).join("") + "</tr>";
  });
  const singles = lab.single.filter((n) => n in lab.servo && !(n in ASN_WORDS))
    .map((n) => `${n} = ${lab.servo[n]}`);
  const note = known.length
    ? `${singles.join(", ")} \u00b7 block 1000's variables, read each 60 Hz tick`
    : "The servo's variables appear once the blocks define them (1000 LOAD): they are found by name in the dictionary.";
  html += `<tr class="note"><td colspan="${lab.perAxis.length + 2}">${note}</td></tr>`;
  if (html !== tableHtml) body.innerHTML = tableHtml = html;   // unchanged: no relayout
  drawAsn();
}

// ---- the ASN (blocks 1070-1078, docs/learning.md): trial, steps, payoff, weights --------------
const ASN_WORDS = { "Trial.No": "trials done", "Steps": "steps", "Z.Was": "payoff", "Late": "late moves" };
let asnText = "", asnWeights = "";
function drawAsn() {
  const box = document.getElementById("asn");
  box.hidden = !("Trial.No" in lab.servo);
  if (box.hidden) return;
  const text = "ASN: " + Object.entries(ASN_WORDS).map(([n, label]) => `${label} ${lab.servo[n]}`).join(", ");
  if (text !== asnText) document.getElementById("asn-text").textContent = asnText = text;
  const w = lab.servo.Weights;
  if (!w || w.join() === asnWeights) return;
  asnWeights = w.join();
  // 4 rows (+x -x +y -y) of 18 inputs (fields along x, then y): red positive, blue negative
  const canvas = document.getElementById("asn-weights"), g = canvas.getContext("2d");
  const cols = w.length / 4, cw = canvas.width / cols, ch = canvas.height / 4;
  const top = Math.max(1, ...w.map(Math.abs));
  w.forEach((v, i) => {
    const a = Math.abs(v) / top;
    g.fillStyle = v >= 0 ? `rgba(200,40,40,${a})` : `rgba(40,80,200,${a})`;
    g.clearRect((i % cols) * cw, Math.floor(i / cols) * ch, cw, ch);
    g.fillRect((i % cols) * cw, Math.floor(i / cols) * ch, cw - 1, ch - 1);
  });
}

// ---- the frame loop -------------------------------------------------------------------------
// Drawn when something changed (new data comes about 30 times a second, or the
// user changed the view): an unchanged frame is not drawn again, which halves
// what the page costs the host.
let lastTable = 0;
function frame(now) {
  if (lab.dirty && AXES.length) {     // nothing to draw before the hello
    lab.dirty = false;
    drawStatus();
    drawRobot();
    drawScope();
    lab.frames = (lab.frames || 0) + 1;
  }
  if (now - lastTable > 100) { drawTable(); lastTable = now; }
  requestAnimationFrame(frame);
}
window.addEventListener("resize", () => { fitTerminal(); lab.dirty = true; });
document.addEventListener("click", () => { lab.dirty = true; });
requestAnimationFrame(frame);
