-- The page of `pointcalc serve` (interp/serve.c): static HTML and a small script.  It asks the
-- server for the script's sliders (/params) and text (/script), shows the figure
-- (/render?name=value&...) scaled to the window with the script beside it, and re-renders when
-- a slider moves (mouse or keyboard) or the script file changes (/version is polled); an error
-- shows its line, marked in the script, and the last good figure stays.  The figure downloads
-- as SVG, PNG (/render?...&format=png) and, where the server renders PDF, as PDF.
return [==[<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>pointcalc live</title>
<meta name="viewport" content="width=device-width, initial-scale=1">
<style>
* { box-sizing: border-box; }
html, body { height: 100%; }
body { font-family: sans-serif; background: #222; color: #eee; margin: 0; display: flex;
       flex-direction: column; }
header { padding: .4em 1em; display: flex; flex-wrap: wrap; align-items: center; gap: .3em 1.5em; }
header h1 { font-size: 1.2em; margin: 0; font-family: monospace; }
#sliders { display: flex; flex-wrap: wrap; gap: .2em 1.5em; }
.slider { display: flex; align-items: center; gap: .4em; }
.slider label { font-family: monospace; }
.slider output { display: inline-block; min-width: 4em; font-family: monospace; text-align: right; }
#downloads { margin-left: auto; }
button, a.button { background: #444; color: #eee; border: 1px solid #666; border-radius: 3px;
       padding: .15em .6em; font: inherit; cursor: pointer; text-decoration: none; }
button:focus, input:focus, a.button:focus { outline: 2px solid #6af; }
main { flex: 1; display: flex; min-height: 0; gap: 1em; padding: 0 1em 1em; }
#figure { flex: 1 1 60%; min-width: 0; display: flex; align-items: flex-start; justify-content: center; }
#figure svg { width: 100%; height: auto; max-height: calc(100vh - 6em); border: 1px solid #444; }
#side { flex: 0 1 40%; min-width: 16em; display: flex; flex-direction: column; min-height: 0; }
#error { background: #611; color: #fdd; padding: .5em; white-space: pre-wrap; font-family: monospace;
         margin: 0 0 .5em; }
#script { flex: 1; overflow: auto; margin: 0; background: #1a1a1a; border: 1px solid #444;
          font-size: 13px; line-height: 1.35; counter-reset: line; }
#script span { display: block; padding-right: .5em; white-space: pre; }
#script span::before { counter-increment: line; content: counter(line); display: inline-block;
          width: 3em; margin-right: .8em; text-align: right; color: #777; }
#script span.failing { background: #611; }
@media (max-width: 800px) { main { flex-direction: column; } #side { min-height: 20em; } }
</style></head><body>
<header>
<h1 id="title">pointcalc live</h1>
<div id="sliders"></div>
<div id="downloads">
<button id="download-svg" title="download the figure as SVG">SVG</button>
<button id="download-png" title="download the figure as PNG">PNG</button>
<button id="download-pdf" title="download the figure as PDF (the print look)" hidden>PDF</button>
</div>
</header>
<main>
<div id="figure" role="img" aria-label="the figure"></div>
<div id="side">
<div id="error" hidden></div>
<pre id="script" aria-label="the script"></pre>
</div>
</main>
<script>
"use strict";
const values = {}, params = {};
let version = null, busy = false, again = false, playing = null, scriptName = "figure";

function query(extra) {
  const q = Object.entries(values).map(([k, v]) => k + "=" + encodeURIComponent(v));
  if (extra) q.push(extra);
  return q.join("&");
}

// The number of decimals a slider shows: its step's (an integer step shows integers); without a
// step, enough for a hundredth of its range.
function decimals(p) {
  const step = p.step > 0 ? p.step : (p.max - p.min) / 100;
  if (!(step > 0)) return 0;
  const s = String(step);
  if (/e-/.test(s)) return Number(s.split("e-")[1]);
  const dot = s.indexOf(".");
  return p.step > 0 ? (dot < 0 ? 0 : s.length - dot - 1) : Math.max(0, -Math.floor(Math.log10(step)));
}
function show(p, v) { return Number(v).toFixed(decimals(p)); }

function markLine(line) {
  for (const s of document.querySelectorAll("#script span.failing")) s.classList.remove("failing");
  const s = line && document.querySelectorAll("#script span")[line - 1];
  if (s) { s.classList.add("failing"); s.scrollIntoView({block: "nearest"}); }
}
function errorLine(text) {
  const m = /:(\d+):/.exec(text);   // "script.lua:LINE: message"
  return m ? Number(m[1]) : 0;
}

async function render() {
  if (busy) { again = true; return; }
  busy = true;
  try {
    const r = await fetch("/render?" + query());
    const text = await r.text();
    const err = document.getElementById("error");
    if (r.ok) {
      document.getElementById("figure").innerHTML = text;
      err.hidden = true;
      markLine(0);
    } else {
      err.textContent = text;       // the last good figure stays
      err.hidden = false;
      markLine(errorLine(text));
    }
    document.body.dataset.rendered = String(Number(document.body.dataset.rendered || 0) + 1);
  } finally {
    busy = false;
    if (again) { again = false; render(); }
  }
}

function play(p, input, out) {
  if (playing) { clearInterval(playing); playing = null; return; }
  const step = p.step > 0 ? p.step : (p.max - p.min) / 60;
  playing = setInterval(() => {
    let v = Number(input.value) + step;
    if (v > p.max) v = p.min;
    input.value = v; out.value = show(p, v); values[p.name] = v;
    render();
  }, 100);
}

async function loadScript() {
  const r = await fetch("/script");
  const box = document.getElementById("script");
  box.textContent = "";
  if (!r.ok) return;
  for (const line of (await r.text()).replace(/\n$/, "").split("\n")) {
    const s = document.createElement("span");
    s.textContent = line;
    box.append(s);
  }
}

async function loadParams() {
  const j = await (await fetch("/params")).json();
  document.getElementById("title").textContent = j.script;
  scriptName = j.script.replace(/\.[^.]*$/, "");
  const box = document.getElementById("sliders");
  box.innerHTML = "";
  for (const p of j.params) {
    params[p.name] = p;
    if (!(p.name in values) || values[p.name] < p.min || values[p.name] > p.max) values[p.name] = p.default;
    const div = document.createElement("div");
    div.className = "slider";
    const label = document.createElement("label");
    label.textContent = p.name;
    label.htmlFor = "slider-" + p.name;
    const input = document.createElement("input");
    input.type = "range"; input.id = "slider-" + p.name;
    input.min = p.min; input.max = p.max;
    // a step for the arrow keys too: the slider's own, else a hundredth of the range
    input.step = p.step > 0 ? p.step : (p.max - p.min) / 100;
    input.value = values[p.name];
    const out = document.createElement("output");
    out.htmlFor = input.id;
    out.value = show(p, values[p.name]);
    input.addEventListener("input", () => {
      values[p.name] = Number(input.value);
      out.value = show(p, input.value);
      render();
    });
    div.append(label, input, out);
    if (p.animate) {
      const b = document.createElement("button");
      b.textContent = "play";
      b.addEventListener("click", () => play(p, input, out));
      div.append(b);
    }
    box.append(div);
  }
  if (j.error) markLine(errorLine(j.error));
}

function save(blob, ext) {
  const a = document.createElement("a");
  a.href = URL.createObjectURL(blob);
  a.download = scriptName + "." + ext;
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(a.href), 1000);
  document.body.dataset.downloaded = a.download;
}
async function download(format) {
  if (format === "svg") {
    const svg = document.querySelector("#figure svg");
    if (svg) save(new Blob([svg.outerHTML], {type: "image/svg+xml"}), "svg");
    return;
  }
  const r = await fetch("/render?" + query("format=" + format));
  if (r.ok) save(await r.blob(), format);
  else { const e = document.getElementById("error"); e.textContent = await r.text(); e.hidden = false; }
}
for (const f of ["svg", "png", "pdf"]) {
  document.getElementById("download-" + f).addEventListener("click", () => download(f));
}
// PDF only where the server renders it (the print renderer)
fetch("/render?format=pdf").then(r => {
  if (r.ok && (r.headers.get("content-type") || "").includes("pdf")) {
    document.getElementById("download-pdf").hidden = false;
  }
}).catch(() => {});

async function poll() {
  try {
    const v = await (await fetch("/version")).text();
    if (v !== version) { version = v; await loadScript(); await loadParams(); await render(); }
  } catch (e) { /* the server went away: keep the page */ }
  setTimeout(poll, 500);
}
poll();
</script></body></html>
]==]
