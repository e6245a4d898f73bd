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
  stops: {}, status: { time: 0, tick: 0, state: "run", speed: "real", power: "off", clock: "count" },
  servo: {}, perAxis: [], single: [], traces: [], latest: [],
  rowsSeen: 0, ended: false, connected: false,
  keyboard: { holder: null, you: false }, outbox: "", room: 4096, errors: [],
};
window.lab = lab;

// ---- the terminal --------------------------------------------------------------------
const term = new Terminal({
  fontFamily: '"DejaVu Sans Mono", monospace', fontSize: 17, cursorBlink: false,   // lab-cursor.js
  scrollback: 5000, theme: { background: "#000000", foreground: "#e6edf3", cursor: "#f0883e" },
});
const fit = new FitAddon.FitAddon();
term.loadAddon(fit);
term.open(document.getElementById("terminal"));
function fitTerminal() {           // the largest font that shows the FORTH's 80 columns,
  let size = 19;                    // times the text size (A- A+: lab-teach.js); larger
  for (; size >= 12; size--) {      // than that, the FORTH's longer lines wrap
    term.options.fontSize = size;
    const dims = fit.proposeDimensions();
    if (dims && dims.cols >= 80) break;
  }
  term.options.fontSize = Math.round(Math.max(size, 12) * (lab.fontScale || 1));
  fit.fit();
}
fitTerminal();
// Fitted again whenever the terminal's box changes, at the next frame: the window's
// size, and whatever comes and goes above or below it in the console panel (the
// keyboard's note, the characters waiting, the typed-ahead line).
let fitAsked = false;
new ResizeObserver(() => {
  if (fitAsked) return;
  fitAsked = true;
  requestAnimationFrame(() => { fitAsked = false; fitTerminal(); });
}).observe(document.getElementById("terminal"));
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
  put(box, waiting ? `${waiting} characters waiting for the machine` : "");
  if (box.hidden !== !waiting) box.hidden = !waiting;
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
  else if (m.t === "history") showHistory(m);        // lab-panel.js
  else if (m.t === "program") showProgram(m);        // lab-program.js
  else if (m.t === "checked") showChecked(m);        // lab-teach.js
  else if (m.t === "hello") {
    learnPlant(m.plant);
    Object.assign(lab, { stops: m.stops, perAxis: m.per_axis, single: m.single, status: m.status });
    term.write(m.con);
    buildTable();
    scope.start();                   // lab-scope.js: its channels, from the plant's columns
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
  scopeTake(m);                      // lab-scope.js: the words' changes
  const cutoff = lab.status.time - KEEP_S;
  for (const trace of lab.traces) {
    let drop = 0;
    while (drop < trace.length && trace[drop][ROW.time_s] < cutoff) drop++;
    if (drop) trace.splice(0, drop);
  }
}

// ---- time control ----------------------------------------------------------------------
// The page changes an element only when what it shows changes: a write of the same
// text or attribute still costs Chromium a style, layout and paint pass, 30 times a
// second (docs/lab.md, Cost).
function put(element, text) {
  if (element.textContent !== text) element.textContent = text;
}
function putAttribute(element, name, value) {
  if (element.getAttribute(name) !== value) element.setAttribute(name, value);
}
function setBadge(kind, text) {
  const badge = document.getElementById("state");
  if (badge.className !== "badge " + kind) badge.className = "badge " + kind;
  put(badge, text);
}
document.querySelectorAll("#speeds button").forEach((b) =>
  b.addEventListener("click", () => send({ t: "speed", v: b.dataset.speed })));
document.getElementById("pause").addEventListener("click", () =>   // at sim> (a step, a
  send({ t: lab.status.state === "pause" || lab.status.prompt ? "run" : "pause" }));   // breakpoint): Run
document.getElementById("step").addEventListener("click", () => send({ t: "step" }));
document.getElementById("power").addEventListener("click", () =>
  send({ t: "power", v: lab.status.power === "on" ? "off" : "on" }));
document.getElementById("clock").addEventListener("click", () =>
  send({ t: "clock", v: lab.status.clock === "timed" ? "count" : "timed" }));

function drawStatus() {
  const s = lab.status;
  put(document.getElementById("simtime"), `${s.time.toFixed(3)} s`);
  const timed = s.clock === "timed";   // what a simulated second is: docs/plots.md
  put(document.getElementById("simtick"), `tick ${s.tick} \u00b7 ${timed ? "11/23 time" : "by count"}`);
  if (!lab.ended) {
    const speedText = { real: "\u00d71", x10: "\u00d710", full: "FULL" }[s.speed] || "";
    if (s.prompt) setBadge("pause", "STOPPED sim>");   // SIMH has the machine stopped
    else if (s.state === "pause") setBadge("pause", "PAUSED");
    else setBadge("run", `RUN ${speedText}`);
  }
  put(document.getElementById("pause"), s.state === "pause" || s.prompt ? "Run" : "Pause");
  const power = document.getElementById("power");
  put(power, s.power === "on" ? "Turn amps off" : "Turn amps on");  // what a click does
  putAttribute(power, "title", `the amplifier rack is ${s.power.toUpperCase()}: click to switch it ` +
    `${s.power === "on" ? "off" : "on"} (SET PLANT POWER)`);
  putAttribute(power, "aria-pressed", String(s.power === "on"));
  power.classList.toggle("on", s.power === "on");
  drawClock(s, timed);
  typedAhead.status(s);
  document.querySelectorAll("#speeds button").forEach((b) =>
    b.classList.toggle("on", b.dataset.speed === s.speed));
}

// The time base's switch: the instruction count (300 000 a simulated second) or the
// 11/23's own clock (each instruction its KDF11-A time), where the simulator prices.
function drawClock(s, timed) {
  const clock = document.getElementById("clock");
  put(clock, timed ? "11/23 time" : "by count");
  putAttribute(clock, "aria-pressed", String(timed));
  clock.classList.toggle("on", timed);
  if (clock.disabled === !!s.timable) clock.disabled = !s.timable;
  putAttribute(clock, "title", !s.timable
    ? "simulated time is the instruction count, 300 000 a second; the 11/23's own clock " +
      "needs the simulator that prices each instruction: start the lab with --timed (make lab TIMED=1)"
    : timed ? "each instruction takes its KDF11-A time (SET CLK TIMED): click for the count, " +
              "300 000 instructions a second"
            : "simulated time is the instruction count, 300 000 a second: click for the 11/23's " +
              "own clock, each instruction its KDF11-A time (SET CLK TIMED)");
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

// ---- the scope: lab-scope.js --------------------------------------------------------

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
    : "The servo's variables appear once 1000 LOAD defines them (found by name).";   // one line at 1280
  html += `<tr class="note"><td colspan="${lab.perAxis.length + 2}">${note}</td></tr>`;
  if (html !== tableHtml) body.innerHTML = tableHtml = html;   // unchanged: no relayout
  drawAsn();
}

// ---- the ASN (blocks 1070-1078, docs/learning.md): trial, steps, payoff, weights --------------
const ASN_WORDS = { "Trial.No": "trials done", "Steps": "steps", "Z.Was": "payoff", "Late": "late moves" };
let asnText = "", asnWeights = "";
function drawAsn() {
  const box = document.getElementById("asn"), shown = "Trial.No" in lab.servo;
  if (box.hidden === shown) box.hidden = !shown;     // as put(): unchanged, not written
  if (!shown) return;
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
// user changed the view): setting lab.dirty asks for animation frames, which go on
// while data comes (KEEP_FRAMES_MS: a frame clock started anew for each message
// would come late and draw two messages in one). Nothing changed for that long, no
// frame is asked for: a paused page costs the host next to nothing.
const KEEP_FRAMES_MS = 250;
let dirty = true, frameAsked = false, lastDrawn = -Infinity;
Object.defineProperty(lab, "dirty", {
  get: () => dirty,
  set: (value) => {
    dirty = value;
    if (dirty && !frameAsked) { frameAsked = true; requestAnimationFrame(frame); }
  },
});
function frame(now) {
  frameAsked = false;
  if (dirty && AXES.length) {         // nothing to draw before the hello (it sets dirty)
    dirty = false;
    lastDrawn = now;
    drawStatus();
    if (!document.getElementById("robot-panel").hidden) drawRobot();   // another view (lab-teach.js)
    drawScope();
    lab.frames = (lab.frames || 0) + 1;
  }
  if (now - lastDrawn < KEEP_FRAMES_MS) { frameAsked = true; requestAnimationFrame(frame); }
}
window.addEventListener("resize", () => { lab.dirty = true; });   // the terminal refits itself
document.addEventListener("click", () => { lab.dirty = true; });
setInterval(drawTable, 100);
lab.dirty = true;
