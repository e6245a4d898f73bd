// The program pane: a block as the lab's disk holds it, each line with the code
// it laid down (the server's `program` message: harness/lab/program_pane.py,
// from harness/analysis/listing.py), the line the front panel's BLK and >IN point
// at highlighted; and a block editor that types the editor's words
// (forth/EDITOR.md) at the FORTH through the keyboard, as a student would.
"use strict";

const program = {                  // window.lab.program for tests
  block: null, lines: [], code: [], why: null, follow: true, shownAt: null, editing: null,
  wanted: null,
};
lab.program = program;

function askBlock(block) {
  program.wanted = block;           // answers to earlier questions are not shown
  send({ t: "program", block });
}

function showProgram(m) {          // the server's answer (lab.js's dispatch)
  if (m.block !== program.wanted || program.editing !== null) return;
  Object.assign(program, { block: m.block, lines: m.lines, code: m.code, why: m.why });
  program.shownAt = null;
  const field = document.getElementById("program-block");
  if (document.activeElement !== field) field.value = m.block;   // not under the user's typing
  drawProgram();
}

function programNote(text) {
  document.getElementById("program-note").textContent = text;
}

function drawProgram() {
  const box = document.getElementById("program-text");
  box.replaceChildren();
  program.lines.forEach((text, i) => {
    const row = document.createElement("div");
    row.className = "pl";
    row.dataset.line = i;
    const head = document.createElement("div");
    head.className = "pl-text";
    head.textContent = `${String(i).padStart(2)} ${text.trimEnd()}`;
    row.append(head);
    for (const code of program.code[i] || []) {
      const c = document.createElement("div");
      c.className = "pl-code";
      c.textContent = code;
      row.append(c);
    }
    box.append(row);
  });
  programNote(program.why || (program.block === null ? "" :
    `block ${program.block} as the disk holds it (FLUSH writes your changes there), ` +
    "each line with the code it laid down (python -m harness listing)"));
  markLine();
}

// Where the machine is: at a breakpoint, the line that defines the word it stopped
// in (the server's `history` message: harness/lab/word_source.py); else the front
// panel's BLK and >IN (front_panel.py), while a block loads. Highlighted while the
// machine is stopped (paused or at sim>).
function markLine() {
  const s = lab.status, stopped = s.state === "pause" || s.prompt;
  const broke = s.prompt && lab.stoppedIn, where = broke ? lab.stoppedIn : lab.panel && lab.panel.loading;
  const at = where && where.block === program.block && stopped ? where.line : null;
  const title = at === null ? "" : broke ? `stopped in ${where.word}: defined in block ${where.block}, line ${where.line}`
    : `stopped in block ${where.block}, line ${where.line}`;
  if (at === program.shownAt && title === program.title) return;
  program.shownAt = at;
  program.title = title;
  document.querySelectorAll("#program-text .pl").forEach((row) => {
    const here = Number(row.dataset.line) === at;
    row.classList.toggle("current", here);
    if (here) row.scrollIntoView({ block: "nearest" });
  });
  const pc = broke && at !== null ? where.pc : null;      // the instruction it stopped at
  document.querySelectorAll("#program-text .pl-code").forEach((row) => {
    const here = pc !== null && row.textContent.trim().startsWith(pc + " ");
    row.classList.toggle("pc", here);
    if (here) row.scrollIntoView({ block: "nearest" });
  });
  document.getElementById("program-where").textContent = title;
}

function showWhere(where) {        // a breakpoint hit (lab-panel.js): its word's block, shown
  if (program.editing !== null) return;
  showView("program-panel");        // lab-teach.js
  askBlock(where.block);
}

function followMachine() {
  const where = lab.panel && lab.panel.loading;
  if (program.sawPrompt && !lab.status.prompt) lab.stoppedIn = null;   // running again: past it
  program.sawPrompt = !!lab.status.prompt;
  if (program.follow && !lab.stoppedIn && where && where.block !== program.block && program.editing === null
      && where.block !== program.asked) {
    program.asked = where.block;
    askBlock(where.block);
  }
  markLine();
}
setInterval(followMachine, 200);

document.getElementById("program-form").addEventListener("submit", (e) => {
  e.preventDefault();
  const n = Number(document.getElementById("program-block").value);
  if (Number.isInteger(n)) askBlock(n);
});

// ---- the editor: 16 lines of 64 characters, typed at the FORTH -----------------------
const LINE = 64;
const printable = (text) => /^[\x20-\x7e]*$/.test(text);

function editLines() {
  return [...document.querySelectorAll("#program-editor input")].map((i) => i.value);
}

function openEditor() {
  if (program.block === null) { programNote("show a block first"); return; }
  const box = document.getElementById("program-lines");
  box.replaceChildren();
  program.lines.forEach((text, i) => {
    const label = document.createElement("label");
    label.textContent = String(i).padStart(2);
    const input = document.createElement("input");
    input.maxLength = LINE;
    input.size = LINE;
    input.spellcheck = false;
    input.autocomplete = "off";
    input.value = text.trimEnd();
    input.setAttribute("aria-label", `block ${program.block} line ${i}`);
    label.append(input);
    box.append(label);
  });
  program.editing = program.block;
  program.follow = false;
  document.getElementById("program-text").hidden = true;
  document.getElementById("program-editor").hidden = false;
  programNote(`editing block ${program.block}: UPDATE types the changed lines ` +
    "with the editor's P and E; FLUSH writes them to the disk");
}

function closeEditor() {
  program.editing = null;
  program.follow = true;
  document.getElementById("program-text").hidden = false;
  document.getElementById("program-editor").hidden = true;
}

// The lines a student would type for the changes: n LIST EDITOR, k P text (k E for
// a blank line), FORTH. Refused (nothing typed) when the page may not type.
function editorTyping(block, before, after) {
  const changed = after.map((t, i) => [i, t.trimEnd()])
    .filter(([i, t]) => t !== (before[i] || "").trimEnd());
  if (!changed.length) return null;
  return [`${block} LIST EDITOR`]
    .concat(changed.map(([i, t]) => (t.trim() ? `${i} P ${t}` : `${i} E`)), ["FORTH"]);
}

function mayType() {
  if (lab.keyboard.holder !== null && !lab.keyboard.you)
    return `${lab.keyboard.holder} holds the keyboard: take it to type here`;
  if (lab.status.prompt) return "the machine is at sim>: CONT first";
  return null;
}

function typeLines(lines) {
  const why = mayType();
  if (why) { programNote(why); return false; }
  lab.type(lines.map((l) => l + "\r").join(""));
  return true;
}
lab.typeLines = typeLines;          // the lessons pane types the same way

function update() {
  const after = editLines(), bad = after.findIndex((t) => !printable(t) || t.length > LINE);
  if (bad >= 0) { programNote(`line ${bad}: printable ASCII only, at most ${LINE} characters`); return; }
  const lines = editorTyping(program.editing, program.lines, after);
  if (!lines) { programNote("nothing changed"); return; }
  if (typeLines(lines)) {
    program.lines = after.map((t) => t.padEnd(LINE));
    programNote(`typed ${lines.length - 2} changed lines at the console; FLUSH writes them to the disk`);
  }
}

function flush() {
  if (!typeLines(["FLUSH"])) return;
  const block = program.editing === null ? program.block : program.editing;
  closeEditor();
  programNote("FLUSH typed: the pane reads the disk again when it answers ok");
  for (const wait of [1000, 3000, 8000]) setTimeout(() => askBlock(block), wait);
}

document.getElementById("program-edit").addEventListener("click", openEditor);
document.getElementById("program-update").addEventListener("click", update);
document.getElementById("program-flush").addEventListener("click", flush);
document.getElementById("program-cancel").addEventListener("click", () => {
  closeEditor();
  drawProgram();
});
