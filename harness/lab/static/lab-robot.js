// The robot panel (loaded after lab.js, whose helpers it uses: sized, stopsOf,
// position, atStop, goal, target, label, units, COLORS, ROW, lab).
//
// One coordinate system the teacher can read: the servo's counts since
// Set.Up.Robot (block 1011, Initialize.Counter started each counter where its
// axis stood), the plant's inches beside them. The drawing itself is the plant's
// work area between its end stops; the zero Set.Up.Robot chose is drawn where it
// lies on the plant (position - counter), as the origin of the counts.
"use strict";

const TRAIL_S = 10;                // the fading trail: the last TRAIL_S simulated seconds
const TARGETS_KEPT = 6;            // earlier Desire.Pos targets shown as numbered marks
const FADE_STEPS = 12;             // the trail drawn in this many alpha bands
const GRIP_OPEN_IN = 2.0;          // the fingers fully open (pdp11-devices/plant/gripper.c)

const robotView = { trail: 0, origin: null, targets: [], fingers: null };
lab.robotView = robotView;         // for tests

function origin(axis) {            // where on the plant the counter reads 0
  const row = lab.latest[axis];
  return row && goal(axis) !== null ? row[ROW.pos] - row[ROW.counter] : null;
}

function noteTargets() {           // a new Desire.Pos: remembered, with the zero it counts from
  const d = lab.servo["Desire.Pos"];
  if (!d) { robotView.targets = []; return; }
  const last = robotView.targets[robotView.targets.length - 1];
  if (last && last.d.every((v, i) => v === d[i])) return;
  robotView.targets.push({ d: d.slice(), at: [0, 1, 2].map(origin) });
  robotView.targets.splice(0, robotView.targets.length - TARGETS_KEPT);
}

function trailPoints() {           // [time, x, y] where both axes have a sample of that time
  const xs = lab.traces[0] || [], ys = lab.traces[1] || [], since = lab.status.time - TRAIL_S;
  const points = [];
  let j = 0;
  for (const r of xs) {
    const t = r[ROW.time_s];
    if (t < since) continue;
    while (j < ys.length && ys[j][ROW.time_s] < t) j++;
    if (j < ys.length && ys[j][ROW.time_s] === t) points.push([t, r[ROW.pos], ys[j][ROW.pos]]);
  }
  return points;
}

function drawTrail(g, px, py, points) {   // older is fainter; a gap (a fast run's skip) breaks it
  const now = lab.status.time, band_s = TRAIL_S / FADE_STEPS;
  g.strokeStyle = "#a5d6ff";
  g.lineWidth = 2.5;
  let band = -1, X0 = null, Y0 = null;   // the band drawn, the path's last point (null: none)
  for (let k = 1; k < points.length; k++) {
    const [t, x, y] = points[k], [t0, x0, y0] = points[k - 1];
    const b = Math.min(FADE_STEPS - 1, Math.max(0, Math.floor((t - (now - TRAIL_S)) / band_s)));
    if (b !== band) {                     // one path per alpha band, in time order
      if (band >= 0) g.stroke();
      band = b;
      g.globalAlpha = 0.1 + 0.9 * (band + 1) / FADE_STEPS;
      g.beginPath();
      X0 = null;
    }
    if (t - t0 > GAP_S * 2) { X0 = null; continue; }
    const X = px(x), Y = py(y);
    if (X0 === null) { X0 = px(x0); Y0 = py(y0); g.moveTo(X0, Y0); }
    // a point less than half a pixel on adds nothing to the picture but a join to
    // stroke (the axes hunt round a target: thousands of them); the last one is kept
    if (Math.abs(X - X0) + Math.abs(Y - Y0) < 0.5 && k < points.length - 1) continue;
    g.lineTo(X, Y);
    X0 = X; Y0 = Y;
  }
  if (band >= 0) g.stroke();
  g.globalAlpha = 1;
}

function drawOrigin(g, px, py, bx, by, bw, bh, ox, oy) {
  g.save();
  g.setLineDash([6, 5]); g.strokeStyle = "#8b949e"; g.lineWidth = 1.2;
  g.beginPath();
  if (px(ox) >= bx && px(ox) <= bx + bw) { g.moveTo(px(ox), by); g.lineTo(px(ox), by + bh); }
  if (py(oy) >= by && py(oy) <= by + bh) { g.moveTo(bx, py(oy)); g.lineTo(bx + bw, py(oy)); }
  g.stroke();
  g.restore();
  const lx = Math.min(Math.max(px(ox) + 5, bx + 4), bx + bw - 112);   // at the area's lower edge
  label(g, "0: Set.Up.Robot", lx, by + bh - 6, "#c9d1d9", "left", 12);
}

function drawTargets(g, px, py) {    // earlier targets: numbered diamonds, the newest brightest
  const n = robotView.targets.length;
  robotView.targets.forEach((t, i) => {
    if (i === n - 1 || t.at[0] === null || t.at[1] === null) return;   // the current one: the ring
    const X = px(t.at[0] + t.d[0]), Y = py(t.at[1] + t.d[1]);
    g.globalAlpha = 0.35 + 0.5 * (i + 1) / n;
    g.strokeStyle = "#f0883e"; g.lineWidth = 2;
    g.beginPath(); g.moveTo(X, Y - 8); g.lineTo(X + 8, Y); g.lineTo(X, Y + 8); g.lineTo(X - 8, Y);
    g.closePath(); g.stroke();
    label(g, String(i + 1 - n), X + 10, Y - 8, "#f0883e", "left", 12);
  });
  g.globalAlpha = 1;
}

function drawFingers(g, X, Y, scale) {   // the gripper, when it is in use: fingers and a held part
  const row = lab.latest[0];
  if (!row || ROW.grip === undefined) return;
  const opening = row[ROW.grip], held = row[ROW.contact] === 1;
  robotView.fingers = { opening, held };
  if (opening >= GRIP_OPEN_IN && !held) return;          // open and idle: not drawn
  const half = Math.max(2, opening * COUNTS_PER_UNIT[0] * scale / 2);
  if (held) {
    g.fillStyle = "#e3b341";
    g.fillRect(X - half, Y - half, 2 * half, 2 * half);
  }
  g.fillStyle = "#f0f6fc";
  g.fillRect(X - half - 6, Y - 16, 6, 32);
  g.fillRect(X + half, Y - 16, 6, 32);
}

function zTrail() {                 // z's samples of the last TRAIL_S seconds
  return (lab.traces[2] || []).filter((r) => r[ROW.time_s] >= lab.status.time - TRAIL_S);
}

// What the picture shows, or null while it changes with time alone (the trail fades:
// x, y or z moved in the last TRAIL_S seconds). An unchanged picture is not drawn
// again: Chromium would redraw and composite the canvas 30 times a second for
// nothing while the robot stands (docs/lab.md, Cost). z standing, its trail's marks
// all lie under z's own bar (drawZ): how many there are does not show.
function robotShows(w, h) {
  const since = lab.status.time - TRAIL_S;
  for (const axis of [0, 1, 2]) {     // newest first, no copies: this runs every frame
    const trace = lab.traces[axis] || [], last = trace[trace.length - 1];
    for (let k = trace.length - 1; k >= 0 && trace[k][ROW.time_s] >= since; k--)
      if (trace[k][ROW.pos] !== last[ROW.pos]) return null;
  }
  const drawn = lab.latest.map((r) => r && [r[ROW.pos], r[ROW.counter], r[ROW.grip], r[ROW.contact]]);
  return JSON.stringify([w, h, window.devicePixelRatio, drawn, lab.servo["Desire.Pos"], lab.stops,
                         robotView.targets]);
}
let robotShown = null;

function drawRobot() {
  const { g, w, h } = sized(document.getElementById("robot"));
  noteTargets();
  const shows = robotShows(w, h);
  if (shows !== null && shows === robotShown) return;
  robotShown = shows;
  const points = trailPoints(), zs = zTrail();
  robotView.trail = points.length;
  g.clearRect(0, 0, w, h);
  const gauge = Math.min(150, w * 0.2), top = 26, bottom = h - 52;
  const sx = stopsOf(0), sy = stopsOf(1);
  const spanX = sx.max - sx.min, spanY = sy.max - sy.min;
  const avail = { w: w - 2 * gauge - 40, h: bottom - top };
  const scale = Math.min(avail.w / spanX, avail.h / spanY);
  const bw = spanX * scale, bh = spanY * scale, bx = 20 + (avail.w - bw) / 2, by = top + (avail.h - bh) / 2;
  const px = (x) => bx + (x - sx.min) * scale, py = (y) => by + bh - (y - sy.min) * scale;
  // the work area, a grid line every inch of the plant, end stops on its edges
  g.fillStyle = "#0b1220";
  g.fillRect(bx, by, bw, bh);
  g.strokeStyle = "#1c2635";
  g.lineWidth = 1;
  for (let x = Math.ceil(sx.min / 800) * 800; x <= sx.max; x += 800) {
    g.beginPath(); g.moveTo(px(x), by); g.lineTo(px(x), by + bh); g.stroke();
  }
  for (let y = Math.ceil(sy.min / 800) * 800; y <= sy.max; y += 800) {
    g.beginPath(); g.moveTo(bx, py(y)); g.lineTo(bx + bw, py(y)); g.stroke();
  }
  const edge = (hit, x0, y0, x1, y1) => {
    g.strokeStyle = hit ? "#ff5c5c" : "#6e7681";
    g.lineWidth = hit ? 7 : 3;
    g.beginPath(); g.moveTo(x0, y0); g.lineTo(x1, y1); g.stroke();
  };
  const stopX = atStop(0), stopY = atStop(1);
  edge(stopX < 0, bx, by, bx, by + bh);
  edge(stopX > 0, bx + bw, by, bx + bw, by + bh);
  edge(stopY < 0, bx, by + bh, bx + bw, by + bh);
  edge(stopY > 0, bx, by, bx + bw, by);
  const ox = origin(0), oy = origin(1);
  robotView.origin = ox === null || oy === null ? null : [ox, oy];
  if (robotView.origin) drawOrigin(g, px, py, bx, by, bw, bh, ox, oy);
  drawTrail(g, px, py, points);
  drawTargets(g, px, py);
  // the gantry: a bridge along y at the carriage's x, the carriage on it
  const x = position(0), y = position(1);
  g.strokeStyle = "#6e7681"; g.lineWidth = 10; g.lineCap = "butt";
  g.globalAlpha = 0.8;
  g.beginPath(); g.moveTo(px(x), by); g.lineTo(px(x), by + bh); g.stroke();
  g.globalAlpha = 1;
  g.fillStyle = "#c9d1d9";
  g.fillRect(px(x) - 14, py(y) - 14, 28, 28);
  g.fillStyle = COLORS[0];
  g.beginPath(); g.arc(px(x), py(y), 6, 0, 2 * Math.PI); g.fill();
  drawFingers(g, px(x), py(y), scale);
  const tx = target(0), ty = target(1);
  if (tx !== null && ty !== null) {
    g.strokeStyle = "#f0883e"; g.lineWidth = 2.5;
    g.beginPath(); g.arc(px(tx), py(ty), 18, 0, 2 * Math.PI); g.stroke();
    g.beginPath(); g.moveTo(px(tx) - 26, py(ty)); g.lineTo(px(tx) + 26, py(ty));
    g.moveTo(px(tx), py(ty) - 26); g.lineTo(px(tx), py(ty) + 26); g.stroke();
  }
  label(g, "top view \u00b7 trail: last 10 s", bx + 6, by + 18, "#8b949e", "left", 13);
  readout(g, 0, bx, h - 28, "left");
  readout(g, 1, bx + bw, h - 28, "right");
  drawZ(g, w - 2 * gauge + 10, top, gauge - 20, bottom - top, zs);
  drawT(g, w - gauge + 10, top, gauge - 20, bottom - top);
}

function counted(axis) {           // counts since Set.Up.Robot: the counter, when the servo is loaded
  const row = lab.latest[axis];
  return row && goal(axis) !== null ? `${row[ROW.counter]}` : null;
}

function readout(g, axis, x, y, align) {   // counts (the servo's) over inches (the plant's)
  const name = AXES[axis].toLowerCase(), c = counted(axis);
  label(g, c === null ? `${name} \u2014 counts` : `${name} ${c} counts`, x, y, COLORS[axis], align, 17);
  label(g, `plant ${units(axis, position(axis))}`, x, y + 20, "#8b949e", align, 14);
}

function drawZ(g, x, y, w, h, zs) {                 // z: a height gauge, stops at its ends
  const s = stopsOf(2), z = position(2), stop = atStop(2), t = target(2);
  const bar = Math.min(46, w * 0.45), bx = x + (w - bar) / 2, top = y + 10, hh = h - 30;
  const py = (v) => top + hh - (v - s.min) / (s.max - s.min) * hh;
  g.fillStyle = "#0b1220"; g.fillRect(bx, top, bar, hh);
  g.fillStyle = COLORS[2];
  zs.forEach((r, i) => {                            // z's trail: faint marks of where it was
    if (i % 8) return;
    g.globalAlpha = 0.08 + 0.3 * i / zs.length;
    g.fillRect(bx + 4, py(r[ROW.pos]) - 1, bar - 8, 2);
  });
  g.globalAlpha = 0.35;
  g.fillRect(bx, py(z), bar, top + hh - py(z)); g.globalAlpha = 1;
  g.fillStyle = COLORS[2]; g.fillRect(bx - 8, py(z) - 4, bar + 16, 8);
  for (const [v, hit] of [[s.min, stop < 0], [s.max, stop > 0]]) {
    g.fillStyle = hit ? "#ff5c5c" : "#6e7681";
    g.fillRect(bx - 12, py(v) - (hit ? 4 : 2), bar + 24, hit ? 8 : 4);
  }
  const oz = origin(2);
  if (oz !== null && oz >= s.min && oz <= s.max) {
    g.strokeStyle = "#8b949e"; g.lineWidth = 1.2; g.setLineDash([4, 4]);
    g.beginPath(); g.moveTo(bx - 14, py(oz)); g.lineTo(bx + bar + 14, py(oz)); g.stroke();
    g.setLineDash([]);
  }
  if (t !== null) {
    g.strokeStyle = "#f0883e"; g.lineWidth = 2.5;
    g.beginPath(); g.moveTo(bx - 18, py(t)); g.lineTo(bx + bar + 18, py(t)); g.stroke();
  }
  label(g, "z", x + w / 2, y + 4, COLORS[2], "center", 17);
  const c = counted(2);
  label(g, c === null ? "z \u2014" : `${c} counts`, x + w / 2, y + h + 24, COLORS[2], "center", 17);
  label(g, `plant ${units(2, z)}`, x + w / 2, y + h + 44, "#8b949e", "center", 14);
}

function drawT(g, x, y, w, h) {                     // t: a dial, 0 degrees up
  const deg = position(3) / COUNTS_PER_UNIT[3], t = target(3), stop = atStop(3);
  const r = Math.min(w, h) / 2 - 8, cx = x + w / 2, cy = y + h / 2;
  g.strokeStyle = stop ? "#ff5c5c" : "#6e7681"; g.lineWidth = stop ? 6 : 3;
  g.beginPath(); g.arc(cx, cy, r, 0, 2 * Math.PI); g.stroke();
  g.strokeStyle = "#30363d"; g.lineWidth = 2;
  for (let a = 0; a < 360; a += 30) {
    const q = (a - 90) * Math.PI / 180;
    g.beginPath(); g.moveTo(cx + Math.cos(q) * (r - 8), cy + Math.sin(q) * (r - 8));
    g.lineTo(cx + Math.cos(q) * r, cy + Math.sin(q) * r); g.stroke();
  }
  const needle = (angle, color, width, length) => {
    const q = (angle - 90) * Math.PI / 180;
    g.strokeStyle = color; g.lineWidth = width;
    g.beginPath(); g.moveTo(cx, cy); g.lineTo(cx + Math.cos(q) * length, cy + Math.sin(q) * length);
    g.stroke();
  };
  if (t !== null) needle(t / COUNTS_PER_UNIT[3], "#f0883e", 2.5, r - 4);
  needle(deg, COLORS[3], 6, r - 14);
  label(g, "t", x + w / 2, y + 4, COLORS[3], "center", 17);
  const c = counted(3);
  label(g, c === null ? "t \u2014" : `${c} counts`, x + w / 2, y + h + 24, COLORS[3], "center", 17);
  label(g, `plant ${deg.toFixed(2)}\u00b0`, x + w / 2, y + h + 44, "#8b949e", "center", 14);
}
