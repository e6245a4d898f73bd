// The terminal's blinking cursor as xterm.js blinks it (each second, half a second in
// the cursor's colours, half a second off; only while the terminal has the focus;
// solid again whenever its row is drawn anew, a key typed or an answer), toggled by a
// timer twice a second. xterm.js's own blink (cursorBlink) is a CSS animation that
// Chromium services at every frame, 60 a second, for a change twice a second: about
// a tenth of a core of headless Chromium's software rendering, paused or running
// (docs/lab.md, Cost). Loaded after lab.js (term); the rule is lab.css's cursor-off.
"use strict";

(() => {
  const HALF_MS = 500;
  const box = document.getElementById("terminal");
  let timer = null;
  function show(on) {
    if (!on) box.style.setProperty("--cursor", (term.options.theme || {}).cursor || "#ffffff");
    box.classList.toggle("cursor-off", !on);
    clearTimeout(timer);
    timer = setTimeout(() => show(!on), HALF_MS);
  }
  term.onRender(({ start, end }) => {   // xterm.js draws the row anew: its animation restarts
    const y = term.buffer.active.cursorY;
    if (start <= y && y <= end) show(true);
  });
  show(true);
})();
