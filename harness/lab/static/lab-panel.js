// The 11/23's front panel (harness/lab/front_panel.py): the registers with their
// FORTH roles, the PSW's fields, the words running (named from the dictionary),
// the block and line being loaded, the bus devices' registers in octal. Redrawn
// ten times a second when a new panel came (none comes while paused) that differs
// from the one shown. Below it, a breakpoint on a FORTH word or on an I/O
// register's access, and a one-instruction step (harness/lab/breakpoints.py);
// when a breakpoint is hit, the instructions before it, each with its word
// (showHistory, from lab.js), and the word's line in the program pane.
// Interrupts per second per vector under the registers.
"use strict";

(() => {
  const box = document.getElementById("front-panel");
  let shown = null, shownHtml = "";
  const cell = (text, cls) => `<span class="${cls || ""}">${text}</span>`;
  const esc = (t) => String(t ?? "\u2014").replace(/[&<>]/g, (c) => ({ "&": "&amp;", "<": "&lt;", ">": "&gt;" })[c]);

  function render(p) {
    const f = p.psw_fields;
    const regs = p.registers.map((r) =>
      `<div class="reg" title="${esc(r.role)}">${cell(r.name, "rn")}${cell(r.value, "rv")}` +
      `${cell(esc(r.role), "rr")}</div>`).join("");
    const flags = ["N", "Z", "V", "C"].map((k) => cell(k, f[k] ? "flag on" : "flag")).join("");
    const devices = p.devices.map((d) => {             // AAV11-A DAC X: "DAC X" is enough
      const name = d.device === "AAV11-A" ? d.register : `${d.device} ${d.register}`;
      return `<div class="dev" title="${d.device} ${d.register} at ${d.address}">` +
        `${cell(name, "rn")}${cell(d.value, "rv")}</div>`;
    }).join("");
    const loading = p.loading ? `loading block ${p.loading.block} line ${p.loading.line}` : "";
    const groups = new Map();        // per board: DL11 060 0 064 0 KW11-L 100 60 ...
    for (const v of p.interrupts || []) {
      const board = v.device.split(" ")[0];
      if (!groups.has(board)) groups.set(board, []);
      groups.get(board).push(`<span title="${esc(v.device)}, vector ${v.vector}: ${v.total} taken ` +
        `since power-up">${v.vector} ${cell(v.per_s === null ? "\u2014" : v.per_s, "rv")}</span>`);
    }
    const rates = [...groups].map(([board, list]) => `${cell(esc(board), "rr")} ${list.join(" ")}`)
      .join(" ");                     // the boards' names (dim) part them
    const html =
      `<div class="fp-head">PDP-11/23 ${cell(`PSW ${p.psw}`, "rv")} priority ${cell(f.priority, "rv")}` +
      ` T ${cell(f.T, "rv")} ${flags} ${cell(f.mode, "dim")}</div>` +
      `<div class="fp-words">PC in ${cell(esc(p.pc_in), "word")} \u00b7 thread of ${cell(esc(p.ip_in), "word")}` +
      ` \u00b7 next ${cell(esc(p.next), "word")} ${cell(loading, "dim")}</div>` +
      `<div class="fp-regs">${regs}</div><div class="fp-devs">${devices}</div>` +
      `<div class="fp-ints" title="interrupts the CPU took per simulated second, per vector (traps are not counted)">` +
      `interrupts/s ${rates || cell("none yet", "dim")}</div>`;
    if (html !== shownHtml) box.innerHTML = shownHtml = html;   // unchanged: no relayout
  }

  setInterval(() => {
    if (lab.panel && lab.panel !== shown) { shown = lab.panel; render(shown); }
  }, 100);
  document.getElementById("break-form").addEventListener("submit", (event) => {
    event.preventDefault();
    const word = document.getElementById("break-word").value.trim();
    if (word) send({ t: "break", word });
  });
  document.getElementById("iobreak-form").addEventListener("submit", (event) => {
    event.preventDefault();
    const address = document.getElementById("iobreak-address").value.trim();
    if (address) send({ t: "iobreak", address: address.slice(0, 8) });
  });
  document.getElementById("stepi").addEventListener("click", () => send({ t: "stepi" }));
  document.getElementById("nobreak").addEventListener("click", () => send({ t: "nobreak" }));
  document.getElementById("history-close").addEventListener("click", () => {
    document.getElementById("history").hidden = true;
  });
})();

function showHistory(m) {           // SHOW CPU HISTORY's rows: PC, PSW, instruction, word
  const rows = m.rows;
  lab.history = rows;
  lab.stoppedIn = m.where;          // lab-program.js marks the word's line
  document.getElementById("history-what").textContent = m.what;
  if (m.where) showWhere(m.where);
  const lines = rows.map(([pc, psw, what, word]) =>
    `${pc} ${psw}  ${what.padEnd(36).slice(0, 36)} ${word || ""}`);
  document.getElementById("history-text").textContent =
    "PC     PSW     instruction                          in word\n" + lines.join("\n");
  const box = document.getElementById("history");
  box.hidden = false;
  box.scrollTop = box.scrollHeight;  // the last row, the instruction it stopped after, in sight
}

