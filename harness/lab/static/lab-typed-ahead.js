// Keys typed while the run is paused wait in the simulator's terminal until it goes
// on (the FORTH echoes them only then): shown under the terminal meanwhile, so that
// typing is not invisible. Loaded before lab.js, which calls typedAhead.status(s)
// with each status and typedAhead.key(d) with each key sent.
"use strict";

const typedAhead = (() => {
  let text = "";
  const box = () => document.getElementById("typed-ahead");
  const paused = (s) => s.state === "pause" && !s.prompt;   // at sim> the server echoes
  function show() {
    box().hidden = !text;
    box().textContent = `typed while paused, reaches the FORTH at Run: ${text.slice(-70)}`;
  }
  function visible(d) {
    let out = text;
    for (const c of d) {
      if (c === "\x7f" || c === "\b") out = out.slice(0, -1);
      else if (c === "\r") out += "\u23ce ";
      else if (c < " ") out += "^" + String.fromCharCode(c.charCodeAt(0) + 64);
      else out += c;
    }
    return out;
  }
  return {
    key(d, status) { if (paused(status)) { text = visible(d); show(); } },
    status(s) { if (!paused(s) && text) { text = ""; show(); } },
  };
})();
