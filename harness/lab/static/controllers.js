// The five machines' page (harness/lab/controllers_page.py): polls /status.
"use strict";
const params = new URLSearchParams(location.search);
const token = params.get("token") || sessionStorage.getItem("controllers-token") || "";
sessionStorage.setItem("controllers-token", token);
history.replaceState(null, "", location.pathname);   // the token off the address bar

function cell(text, cls) {
  const td = document.createElement("td");
  td.textContent = text === null || text === undefined ? "-" : String(text);
  if (cls) td.className = cls;
  return td;
}

function yesNo(v) { return v === null ? "-" : (v ? "yes" : "no"); }

function render(v) {
  if (!v.started) return;
  document.getElementById("time").textContent =
    `simulated time ${v.time_s.toFixed(3)} s (quantum ${v.quantum})`;
  const rack = document.getElementById("rack");
  rack.textContent = v.rack_on ? "amplifier rack: on" : "amplifier rack: OFF (no axis is driven)";
  rack.className = v.rack_on ? "" : "off";
  const machines = document.getElementById("machines");
  machines.replaceChildren(...v.machines.map(m => {
    const div = document.createElement("div");
    div.className = "machine" + (m.state === "lost" ? " lost" : "");
    const h = document.createElement("h3");
    h.textContent = (m.name === "main" ? "PDP-11/23" : `LSI-11/03 ${m.name}`) + `: ${m.state}`;
    const pre = document.createElement("pre");
    pre.textContent = m.console;
    div.append(h, pre);
    return div;
  }));
  document.getElementById("servo").replaceChildren(...v.servo.map(a => {
    const tr = document.createElement("tr");
    tr.append(cell(a.axis, `text axis-${a.axis}`), cell(a.target), cell(a.max_vel), cell(yesNo(a.executing)),
              cell(yesNo(a.moving)), cell(a.counter), cell(a.pos.toFixed(1)),
              cell(a.vel.toFixed(1)), cell(a.dac), cell(a.run),
              cell(a.last_words.join(" "), "text"), cell(a.last_answers.join(" "), "text"));
    return tr;
  }));
}

async function poll() {
  try {
    const r = await fetch(`status?token=${encodeURIComponent(token)}`);
    if (r.ok) render(await r.json());
    else document.getElementById("time").textContent = await r.text();
  } catch (e) {
    document.getElementById("time").textContent = "the session has ended";
  }
}
setInterval(poll, 500);
poll();
