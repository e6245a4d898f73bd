// Teaching mode: which view the robot's place shows (robot, program, lessons),
// the light theme, the text size (every panel's text but the robot's drawing), and the
// lessons: README's first session and docs/exercises.md's five exercises as
// steps, each with the line to type (a button types it at the FORTH through the
// keyboard) and each exercise's check run by the server (`check`, harness/lab/
// lesson_checks.py), showing what it measured.
"use strict";

// ---- views, theme, text size ------------------------------------------------------------
const VIEWS = ["robot-panel", "program-panel", "teach-panel"];
function showView(id) {
  for (const v of VIEWS) document.getElementById(v).hidden = v !== id;
  const nav = document.getElementById("views");
  document.querySelector(`#${id} h2`).append(nav);       // the switch goes with the view
  nav.querySelectorAll("[data-view]").forEach((b) => {
    b.classList.toggle("on", b.dataset.view === id);
    b.setAttribute("aria-pressed", String(b.dataset.view === id));
  });
  lab.view = id;
  lab.dirty = true;
}
document.querySelectorAll("#views [data-view]").forEach((b) =>
  b.addEventListener("click", () => showView(b.dataset.view)));

const DARK_TERMINAL = { background: "#000000", foreground: "#e6edf3", cursor: "#f0883e" };
const LIGHT_TERMINAL = { background: "#ffffff", foreground: "#111418", cursor: "#a4470b",
  selectionBackground: "#b3d1ff" };
function setTheme(theme) {
  document.documentElement.dataset.theme = theme;
  term.options.theme = theme === "light" ? LIGHT_TERMINAL : DARK_TERMINAL;
  const b = document.getElementById("theme");
  b.textContent = theme === "light" ? "Dark" : "Light";        // what a click does
  lab.theme = theme;
  localStorage.setItem("labTheme", theme);
}
document.getElementById("theme").addEventListener("click", () =>
  setTheme(lab.theme === "light" ? "dark" : "light"));

const FONT_SCALES = [0.85, 1, 1.2, 1.45, 1.75];              // the largest is tested to fit
function setFont(step) {
  lab.fontStep = Math.max(0, Math.min(FONT_SCALES.length - 1, step));
  lab.fontScale = FONT_SCALES[lab.fontStep];
  document.documentElement.style.setProperty("--fs", lab.fontScale);
  fitTerminal();                    // lab.js: the terminal's font
  scope.restyle();                  // lab-scope.js: the plot's axes
  document.getElementById("font-down").disabled = lab.fontStep === 0;
  document.getElementById("font-up").disabled = lab.fontStep === FONT_SCALES.length - 1;
  localStorage.setItem("labFont", lab.fontStep);
}
lab.fontScales = FONT_SCALES;
document.getElementById("font-down").addEventListener("click", () => setFont(lab.fontStep - 1));
document.getElementById("font-up").addEventListener("click", () => setFont(lab.fontStep + 1));

setTheme(localStorage.getItem("labTheme") === "light" ? "light" : "dark");
setFont(Number(localStorage.getItem("labFont") || 1));
showView("robot-panel");

// ---- the lessons ---------------------------------------------------------------------------
// A step: what to do and why (text), the line to type (type), or a page action
// (act: "power" switches the rack on as README's ^E SET PLANT POWER=ON CONT does).
const LESSONS = [
  { title: "A first session (README)", steps: [
    { text: "Load the paper's blocks 1000-1012, as printed.", type: "1000 LOAD" },
    { text: "Zero the counters and start the 60 Hz servo on vector 100.", type: "Set.Up.Robot" },
    { text: "Switch the amplifier rack on (at the terminal: ^E, SET PLANT POWER=ON, CONT). " +
            "It boots off so that nothing drifts before the servo holds the axes.", act: "power" },
    { text: "Move x and y one inch; Move.Complete? returns when x, y and z arrive " +
            "(it can wait for ever while an axis hunts: ^C stops it).",
      type: "800 800 0 0 Abs.Move Move.Complete?" },
    { text: "Read the counters: about 800 800, the printed servo hunts round its targets.",
      type: "0 Read.Counter . 1 Read.Counter ." },
    { text: "The project's demonstration block.", type: "1020 LOAD" },
  ] },
  { title: "1. Predict D2 for a 4000-count move", exercise: 1, steps: [
    { text: "Block 1006 sends the distance left as the velocity once it is below MaxVel " +
            "(300 codes). At what distance from D0 does the commanded velocity start to " +
            "fall (D2)? Why can it not be exactly one number? Read the block:", type: "1006 LIST" },
    { text: "Watch a 4000-count move on the scope (after 1000 LOAD and Set.Up.Robot, rack on).",
      type: "4000 0 400 0 Abs.Move" },
  ] },
  { title: "2. Find the missing ELSE", exercise: 2, steps: [
    { text: "The paper promises a ramp: Velocity grows by Increment each tick up to MaxVel. " +
            "Read block 1006 lines 5-9 with the code they laid down (the Program view " +
            "shows the listing). What does the code do instead, and which word, added " +
            "where, would make it the ramp?", type: "1006 LIST" },
    { text: "The check compares the first ticks with the printed blocks and with blocks " +
            "1030-1031 (the project's proposal)." },
  ] },
  { title: "3. Measure the hunting period", exercise: 3, steps: [
    { text: "After a move the servo kicks the axis back and forth round the target. How " +
            "many 60 Hz ticks is one period on x? Same on every axis?",
      type: "800 0 400 0 Abs.Move" },
    { text: "Pause, then Step 1 tick at a time and watch the DAC column of the servo table " +
            "(from one 2349 to the next)." },
  ] },
  { title: "4. Price the servo", exercise: 4, steps: [
    { text: "Estimate from the listing of block 1008 how many instructions one tick runs " +
            "at rest, and what share of the 11/23 that is (about 3.4 us an instruction, " +
            "16 667 us a tick).", type: "1008 LIST" },
    { text: "The check measures it (python -m harness timing --servo idle)." },
  ] },
  { title: "5. Write a block that moves in a square", exercise: 5, steps: [
    { text: "Write block 1100 (Program view: block 1100, Edit; or the editor's words at the " +
            "terminal) so that 1100 LOAD defines Square: x, y visit (1600,0), (1600,1600), " +
            "(0,1600), (0,0), z at 400, two seconds at each corner. Start with:",
      type: "EDITOR 1100 WIPE" },
    { text: "FLUSH, then run the check: it loads your block on a copy of this disk and " +
            "reads the counters at the end (about 0 0).", type: "FLUSH FORTH" },
  ] },
];
lab.lessons = LESSONS;
lab.checks = {};                      // exercise -> the server's `checked` answer

function lessonStep(step, i) {
  const li = document.createElement("li");
  li.append(document.createTextNode(step.text + " "));
  if (step.type) {
    const line = document.createElement("pre");
    line.textContent = step.type;
    li.append(line);
  }
  if (step.type || step.act) {
    const b = document.createElement("button");
    b.type = "button";
    b.className = "teach-do";
    b.dataset.step = i;
    b.textContent = step.type ? "Type it" : "Turn amps on";
    b.addEventListener("click", () => {
      if (step.act === "power") send({ t: "power", v: "on" });
      else if (!lab.typeLines([step.type])) return;            // lab-program.js
      li.classList.add("done");
    });
    li.append(b);
  }
  return li;
}

function drawLesson() {
  const lesson = LESSONS[Number(document.getElementById("teach-lesson").value)];
  const body = document.getElementById("teach-body");
  const list = document.createElement("ol");
  lesson.steps.forEach((s, i) => list.append(lessonStep(s, i)));
  body.replaceChildren(list);
  if (lesson.exercise) {
    const b = document.createElement("button");
    b.type = "button";
    b.id = "teach-check";
    b.textContent = `Run exercise ${lesson.exercise}'s check`;
    b.addEventListener("click", () => {
      lab.checks[lesson.exercise] = null;
      showChecked({ exercise: lesson.exercise, text: "running on the host (a scripted run " +
                    "of its own, not this machine)...", ok: null });
      send({ t: "check", exercise: lesson.exercise });
    });
    const out = document.createElement("div");
    out.id = "teach-measured";
    out.className = "measured";
    out.setAttribute("role", "status");
    out.tabIndex = 0;                  // it scrolls: reachable by keyboard
    out.hidden = true;
    body.append(b, out);
    if (lab.checks[lesson.exercise]) showChecked(lab.checks[lesson.exercise]);
  }
}

function showChecked(m) {            // the server's `checked` (lab.js's dispatch)
  if (m.ok !== null) lab.checks[m.exercise] = m;
  const lesson = LESSONS[Number(document.getElementById("teach-lesson").value)];
  const out = document.getElementById("teach-measured");
  if (!out || lesson.exercise !== m.exercise) return;
  out.hidden = false;
  out.textContent = m.text;
}

const picker = document.getElementById("teach-lesson");
LESSONS.forEach((lesson, i) => picker.append(new Option(lesson.title, i)));
picker.addEventListener("change", drawLesson);
drawLesson();
