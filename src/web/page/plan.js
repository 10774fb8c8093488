"use strict";
// The planner ("Tonight"): GET /api/v1/passes for the chosen satellites (none: the tracking list)
// above a minimum elevation, each pass in the page's zone (UTC or local, labelled) with its maximum, a small
// sky track and the passes it overlaps; one or several chosen and tracked (POST /api/v1/track).
// Uses app.js's $, post, xy, points, el and confirmLeave.
let planned = [], chosen = new Set(), planSats = "";
function planQuery() {
  const names = [...document.querySelectorAll("#plan-sats input:checked")].map((c) => c.value);
  const q = new URLSearchParams();
  if (names.length) q.set("sat", names.join(","));
  q.set("min_el", $("plan-minel").value || "0");
  q.set("hours", $("plan-hours").value || "12");
  const w = $("plan-with").value.trim();
  if (w) q.set("with", w);
  return q.toString();
}
// A pass's AOS with its date, in the page's zone (app.js: clockText, the header's zone button).
function planTime(iso) {
  return new Date(iso).toLocaleDateString([], zoneOpt({ weekday: "short", day: "numeric", month: "short" })) + " " +
         clockText(iso, null, false);
}
let planNote = "";
function planZone() {
  if (planNote) $("plan-note").textContent = planNote + " · times " + zoneName();
  drawPlan();
}
function miniSky(track) {
  const svg = document.createElementNS(SVG, "svg");
  svg.setAttribute("viewBox", "0 0 640 640");
  svg.setAttribute("class", "mini");
  svg.setAttribute("aria-hidden", "true");
  svg.appendChild(el("circle", { cx: C, cy: C, r: R, class: "horizon" }));
  svg.appendChild(el("circle", { cx: C, cy: C, r: R * 2 / 3, class: "ring" }));
  svg.appendChild(el("polyline", { points: points(track), class: "track" }));
  if (track.length) { const [x, y] = xy(track[0][0], track[0][1]); svg.appendChild(el("circle", { cx: x, cy: y, r: 40, class: "start" })); }
  return svg;
}
function drawPlan() {
  const list = $("plan-list");
  list.replaceChildren();
  planned.forEach((p, k) => {
    const li = document.createElement("li");
    li.dataset.index = k;
    li.dataset.satellite = p.satellite;
    li.setAttribute("role", "button");
    li.setAttribute("aria-pressed", chosen.has(k) ? "true" : "false");
    li.tabIndex = 0;
    const text = document.createElement("div");
    const mins = Math.round((Date.parse(p.los) - Date.parse(p.aos)) / 60000);
    const over = p.overlaps.map((o) => planned[o].satellite);
    text.innerHTML = "";
    const b = document.createElement("b");
    b.textContent = p.satellite;
    text.append(b, " " + planTime(p.aos) + (p.in_progress ? " (up now)" : ""));
    const small = document.createElement("small");
    small.textContent = clockText(p.aos, null, false) + "-" + clockText(p.los, null, false) + " " + zoneName() + " · max " +
                        p.max_el_deg.toFixed(0) + "° · " + mins + " min";
    text.append(document.createElement("br"), small);
    if (over.length) {
      const o = document.createElement("span");
      o.className = "overlap";
      o.textContent = "overlaps " + [...new Set(over)].join(", ");
      text.append(document.createElement("br"), o);
    }
    li.append(miniSky(p.track), text);
    li.addEventListener("click", () => {
      if (chosen.has(k)) chosen.delete(k); else chosen.add(k);
      li.setAttribute("aria-pressed", chosen.has(k) ? "true" : "false");
      planChosen();
    });
    list.appendChild(li);
  });
  planChosen();
}
function planChosen() {
  const names = [...new Set([...chosen].map((k) => planned[k].satellite))];
  const b = $("btn-plan-track");
  b.disabled = names.length === 0 || names.length > 5;
  b.textContent = names.length <= 1 ? "Track " + (names[0] || "chosen") : "Track " + names.length + " (multiple)";
  return names;
}
async function plan(ev) {
  if (ev) ev.preventDefault();
  const q = planQuery();
  $("plan-ics").href = "/api/v1/passes.ics?" + q;
  $("plan-note").textContent = "…";
  try {
    const res = await fetch("/api/v1/passes?" + q, { credentials: "same-origin" });
    const j = await res.json();
    if (!res.ok) { $("plan-note").textContent = j.error; return; }
    planned = j.passes;
    chosen = new Set();
    const n = planned.filter((p) => p.overlaps.length).length;
    planNote = planned.length + " passes above " + j.min_el_deg + "° in " + j.hours + " h" +
      (j.with ? ", both seen from " + j.with : "") + (n ? "; " + n + " overlap another" : "");
    planZone();
  } catch (e) {
    $("plan-note").textContent = "the station does not answer";
  }
}
function planTrack() {
  const names = planChosen();
  if (!names.length || !confirmLeave(names.length === 1 ? names[0] : null)) return;
  post("/api/v1/track", names.length === 1 ? { satellite: names[0] } : { list: names });
}
// The satellites to choose from: the tracking list, once it is known (and when it changes).
function planList(st) {
  const names = (st.tracking_list || []).map((e) => e.name);
  if (names.join(",") === planSats) return;
  planSats = names.join(",");
  const want = new Set(["SO-50", "AO-91", "RS-44", "ISS"]);
  const box = $("plan-sats");
  box.replaceChildren(box.firstElementChild || document.createElement("legend"));
  for (const n of names) {
    const l = document.createElement("label");
    const c = document.createElement("input");
    c.type = "checkbox";
    c.value = n;
    c.checked = want.has(n);
    l.append(c, " " + n);
    box.appendChild(l);
  }
}
$("plan-form").addEventListener("submit", plan);
$("btn-plan-track").addEventListener("click", planTrack);
