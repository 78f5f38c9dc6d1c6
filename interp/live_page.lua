-- The page of `pointcalc serve` (interp/serve.c): static HTML and a small script.  It asks the
-- server for the script's sliders (/params), shows the figure (/render?name=value&...) and
-- re-renders when a slider moves or the script file changes (/version is polled); an error
-- shows its line and the last good figure stays.
return [==[<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>pointcalc live</title>
<style>
body { font-family: sans-serif; background: #222; color: #eee; margin: 1em; }
#figure svg { max-width: 100%; height: auto; border: 1px solid #444; }
#error { background: #611; color: #fdd; padding: .5em; white-space: pre-wrap; font-family: monospace; }
.slider { margin: .3em 0; }
.slider label { display: inline-block; min-width: 6em; }
.slider output { display: inline-block; min-width: 5em; font-family: monospace; }
button { margin-left: .5em; }
</style></head><body>
<h1 id="title">pointcalc live</h1>
<div id="sliders"></div>
<div id="error" hidden></div>
<div id="figure"></div>
<script>
"use strict";
const values = {};
let version = null, busy = false, again = false, playing = null;

function query() {
  return Object.entries(values).map(([k, v]) => k + "=" + encodeURIComponent(v)).join("&");
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
    } else {
      err.textContent = text;       // the last good figure stays
      err.hidden = false;
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
    input.value = v; out.value = v.toFixed(4); values[p.name] = v;
    render();
  }, 100);
}

async function loadParams() {
  const j = await (await fetch("/params")).json();
  document.getElementById("title").textContent = j.script;
  const box = document.getElementById("sliders");
  box.innerHTML = "";
  for (const p of j.params) {
    if (!(p.name in values) || values[p.name] < p.min || values[p.name] > p.max) values[p.name] = p.default;
    const div = document.createElement("div");
    div.className = "slider";
    const label = document.createElement("label");
    label.textContent = p.name;
    const input = document.createElement("input");
    input.type = "range"; input.id = "slider-" + p.name;
    input.min = p.min; input.max = p.max;
    input.step = p.step > 0 ? p.step : "any";
    input.value = values[p.name];
    const out = document.createElement("output");
    out.value = Number(values[p.name]).toFixed(4);
    input.addEventListener("input", () => {
      values[p.name] = Number(input.value);
      out.value = Number(input.value).toFixed(4);
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
}

async function poll() {
  try {
    const v = await (await fetch("/version")).text();
    if (v !== version) { version = v; await loadParams(); await render(); }
  } catch (e) { /* the server went away: keep the page */ }
  setTimeout(poll, 500);
}
poll();
</script></body></html>
]==]
