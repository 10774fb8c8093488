"use strict";
// The station's page: the live state over the WebSocket /api/v1/live (reconnecting by itself),
// changes through POST /api/v1/... (docs/web-api.md). No framework, nothing from elsewhere.
const $ = (id) => document.getElementById(id);
const SVG = "http://www.w3.org/2000/svg";
// The sky plot's geometry, as `passes --plot` draws it: north up, east right, zenith in the centre.
const C = 320, R = 270;
function xy(az, el) {
  const r = R * (90 - el) / 90, a = az * Math.PI / 180;
  return [C + r * Math.sin(a), C - r * Math.cos(a)];
}
// A number with d decimals; never "-0" (a maximum of -0.3 shown to the degree).
function fixed(v, d) {
  if (typeof v !== "number") return "-";
  const t = v.toFixed(d);
  return /^-0(\.0*)?$/.test(t) ? t.slice(1) : t;
}
function mhz(hz) { return typeof hz === "number" ? (hz / 1e6).toFixed(5) + " MHz" : "-"; }
function mhz6(hz) { return typeof hz === "number" ? (hz / 1e6).toFixed(6) : "-"; }
function signedHz(v) { return typeof v === "number" ? (v > 0 ? "+" : "") + Math.round(v) + " Hz" : "-"; }
function setText(id, t) { const e = $(id); if (e.textContent !== t) e.textContent = t; }
// Every time on the page in one zone, labelled: the browser's local time or UTC, as the header's
// zone button chooses (kept in this browser). The station's clock is UTC whatever is shown.
let zoneUtc = localStorage.getItem("trakbox-zone") === "utc";
function zoneOpt(o) { return zoneUtc ? Object.assign({ timeZone: "UTC" }, o) : o; }
function zoneName() { return zoneUtc ? "UTC" : "local"; }
function dayKey(d) { return d.toLocaleDateString("en-CA", zoneOpt({})); }
// "19:12:28" (or "19:12" without seconds) in the page's zone, with the date when it is not the day
// of `now` there ("Thu 22 May 03:04:05"); no `now`: the time alone.
function clockText(iso, now, seconds = true) {
  if (!iso) return "-";
  const d = new Date(iso);
  const t = d.toLocaleTimeString([], zoneOpt(seconds ? { hour: "2-digit", minute: "2-digit", second: "2-digit" }
                                                    : { hour: "2-digit", minute: "2-digit" }));
  if (!now || dayKey(d) === dayKey(new Date(now))) return t;
  return d.toLocaleDateString([], zoneOpt({ weekday: "short", day: "numeric", month: "short" })) + " " + t;
}
function el(tag, attrs, text) {
  const e = document.createElementNS(SVG, tag);
  for (const k in attrs) e.setAttribute(k, attrs[k]);
  if (text !== undefined) e.textContent = text;
  return e;
}
function points(list) { return list.map((p) => xy(p[0], p[1]).map((v) => v.toFixed(1)).join(",")).join(" "); }

function drawGrid() {
  const g = $("grid");
  for (const e of [0, 30, 60]) g.appendChild(el("circle", { cx: C, cy: C, r: R * (90 - e) / 90 }));
  g.appendChild(el("line", { x1: C - R, y1: C, x2: C + R, y2: C }));
  g.appendChild(el("line", { x1: C, y1: C - R, x2: C, y2: C + R }));
  for (const [t, x, y] of [["N", C, C - R - 12], ["S", C, C + R + 30], ["E", C + R + 22, C + 8], ["W", C - R - 22, C + 8]])
    g.appendChild(el("text", { x, y }, t));
}

// A mark at its azimuth and elevation; one below the horizon (a satellite not yet risen) is drawn
// hollow just outside the horizon ring, where it will rise, not on the ring as if it were up.
function place(id, azel) {
  const e = $(id);
  if (!azel) { e.setAttribute("cx", -99); e.setAttribute("cy", -99); return; }
  const below = azel[1] < 0;
  const [x, y] = xy(azel[0], below ? -8 : azel[1]);
  e.setAttribute("cx", x.toFixed(2));
  e.setAttribute("cy", y.toFixed(2));
  e.classList.toggle("below", below);
}

// The station's horizon mask (status station.horizon_mask: its points, interpolated or stepped),
// shaded between the horizon ring and the mask's elevation, as the station computes it.
function maskAt(m, az) {
  const p = m.points;
  if (m.kind === "stepped") {
    for (let i = p.length - 2; i >= 0; --i) if (az >= p[i][0] && az < p[i + 1][0]) return p[i][1];
    return p[p.length - 2][1];
  }
  if (p.length === 1) return p[0][1];
  let k = p.findIndex((q) => q[0] > az);
  const b = k < 0 ? p[0] : p[k], a = k === 0 ? p[p.length - 1] : k < 0 ? p[p.length - 1] : p[k - 1];
  let span = b[0] - a[0], off = az - a[0];
  if (span <= 0) span += 360;
  if (off < 0) off += 360;
  return span <= 0 ? a[1] : a[1] + (b[1] - a[1]) * Math.min(1, off / span);
}
let maskDrawn = "";
function drawMask(m) {
  const key = m ? JSON.stringify(m.points) + m.kind : "";
  if (key === maskDrawn) return;
  maskDrawn = key;
  $("k-mask").hidden = !m;
  if (!m) { $("mask").setAttribute("points", ""); return; }
  const edge = [], ring = [];
  for (let az = 0; az <= 360; az += 1) {
    edge.push([az, Math.max(0, maskAt(m, az % 360))]);
    ring.unshift([az, 0]);
  }
  $("mask").setAttribute("points", points(edge.concat(ring)));
}

function drawSky(sky) {
  lastSky = sky;
  $("sat-name").textContent = sky.satellite ? sky.satellite.name : "";
  place("sat", sky.satellite ? sky.satellite.az_el : null);
  $("sat").dataset.time = sky.time || "";
  place("antenna", sky.antenna);
  $("ant-word").textContent = sky.antenna_state || "";
  place("target", sky.target);
  const p = sky.pass;
  $("track").setAttribute("points", p ? points(p.track) : "");
  $("planned").setAttribute("points", p && p.planned ? points(p.planned) : "");
  const lost = $("lost"), marks = $("marks");
  lost.replaceChildren();
  marks.replaceChildren();
  $("coverage").textContent = p && p.coverage ? planText(p, lastStatus && lastStatus.antenna) : "";
  if (!p) return;
  let run = [];
  p.track.forEach((pt, i) => {
    if (p.lost && p.lost[i]) run.push(pt);
    else { if (run.length > 1) lost.appendChild(el("polyline", { points: points(run) })); run = []; }
  });
  if (run.length > 1) lost.appendChild(el("polyline", { points: points(run) }));
  // AOS and LOS at the ends of the track drawn (a pass up when tracking began starts where it was);
  // a label that would sit on another's, or on a compass letter, moves a line towards the centre
  // (20 px text in the 640 viewBox; "AOS 10:46:57" is about 150 wide). [left, right, baseline].
  const first = p.track[0], last = p.track[p.track.length - 1];
  const W = 150, LINE = 28;   // a line of 20 px text with its box (about 23 px) and a gap
  const placed = [[C - 12, C + 12, C - R - 12], [C - 12, C + 12, C + R + 30],
                  [C + R + 10, C + R + 34, C + 8], [C - R - 34, C - R - 10, C + 8]];
  for (const [name, t, az, e] of [["AOS", p.aos, first ? first[0] : p.aos_az_deg, first ? first[1] : 0],
                                  ["TCA", p.tca, p.tca_az_deg, p.max_el_deg],
                                  ["LOS", p.los, last ? last[0] : p.los_az_deg, last ? last[1] : 0]]) {
    const [x, y] = xy(az, e);
    marks.appendChild(el("circle", { cx: x, cy: y, r: 5 }));
    const lx = x + (x > C ? -10 : 10);
    const left = x > C ? lx - W : lx, right = x > C ? lx : lx + W;
    let ly = y + (y > C ? 22 : -10);
    const step = ly > C ? -LINE : LINE;
    for (let k = 0, hit; k < 8 && (hit = placed.find(([a, b, py]) => a < right && left < b && Math.abs(py - ly) < LINE)); ++k)
      ly = hit[2] + step;
    placed.push([left, right, ly]);
    marks.appendChild(el("text", { x: lx, y: ly, "text-anchor": x > C ? "end" : "start" }, name + " " + clockText(t, lastStatus && lastStatus.time) + " " + zoneName()));
  }
}

// The pass plan in words, the same in the sky panel and the antenna panel; when the antenna cannot
// follow all of the pass on a 360-degree rotator, the fix: a rotator with overlap and --az-travel 450.
function planText(p, a) {
  if (!p || !p.coverage) return "-";
  let t = p.coverage;
  if (p.coverage_full === false && a && a.az_travel_deg === 360)
    t += ". A rotator with overlap (G-5500, a GS-232 in 450° mode) follows it: trakbox --az-travel 450";
  if (p.keyhole) t += ". " + p.keyhole.charAt(0).toUpperCase() + p.keyhole.slice(1);
  return t;
}

function countdown(iso, now) {
  if (!iso || !now) return "-";
  const s = Math.round((Date.parse(iso) - Date.parse(now)) / 1000);
  if (s <= 0) return "now";
  const h = Math.floor(s / 3600), m = Math.floor(s % 3600 / 60), r = s % 60;
  return (h ? h + "h" : "") + String(m).padStart(h ? 2 : 1, "0") + "m" + String(r).padStart(2, "0") + "s";
}


// The rows are updated in place (a row rebuilt every second would swallow a tap made across a tick).
function drawList(st) {
  const body = $("list").tBodies[0];
  const list = st.tracking_list || [];
  list.forEach((e, k) => {
    let tr = body.rows[k];
    if (!tr || tr.dataset.name !== e.name) {
      const fresh = document.createElement("tr");
      fresh.dataset.name = e.name;
      for (let i = 0; i < 6; ++i) fresh.appendChild(document.createElement("td"));
      fresh.addEventListener("click", () => { if (confirmLeave(e.name)) post("/api/v1/track", { satellite: e.name }); });
      if (tr) body.replaceChild(fresh, tr); else body.appendChild(fresh);
      tr = fresh;
    }
    tr.className = st.tracking && st.tracking.followed === e.name ? "tracked" : "";
    // No pass in the day searched (a satellite that never comes up here: "none", in "> 24 h") and one
    // that never sets (geostationary: "always up") are said, not shown as a blank. A pass in progress
    // shows when it rose and the whole pass's maximum (the status gives the whole pass), "up now".
    const np = e.next_pass;
    const when = !np ? ["none", "", "> 24 h"]
               : np.always_up ? ["always up", fixed(np.max_el_deg, 0) + "°", "up"]
               : [clockText(np.aos, st.time || np.aos), fixed(np.max_el_deg, 0) + "°", np.in_progress ? "up now" : countdown(np.aos, st.time)];
    if (np && np.in_progress && !np.always_up) tr.classList.add("up");
    const cells = [e.number, e.name, ...when, fixed(e.element_age_days, 1) + " d"];
    cells.forEach((c, i) => {
      const td = tr.cells[i];
      if (td.textContent !== String(c)) td.textContent = c;
      td.className = i === 5 && e.elements_stale ? "stale" : "";
    });
  });
  while (body.rows.length > list.length) body.deleteRow(-1);
}

// The Station card: the callsign and place now, what a first start leaves to set (st.setup), open
// by itself once while something is left; Set goes through POST /api/v1/station (the one door).
let stationOpened = false;
function drawStation(st) {
  const s = st.station || {};
  setText("station-now", (s.callsign || "") + " " + (s.locator || ""));
  const setup = st.setup || [];
  setText("station-setup", setup.join(" · "));
  $("station-setup").className = setup.length ? "note bad" : "note";
  if (setup.length && !stationOpened) { $("station-card").open = true; stationOpened = true; }
  // The horizon mask (issue 57): what it is, and its points to edit (one pair a line), refreshed
  // while the operator has not started typing a new one.
  const m = s.horizon_mask;
  setText("st-mask-now", m ? m.describe : "none");
  const shown = m ? (m.kind === "stepped" ? m.text : m.text.split("; ").join("\n")) : "";
  if (!maskEdited && $("st-mask").value !== shown) $("st-mask").value = shown;
}
let maskEdited = false;
async function setStation(ev) {
  ev.preventDefault();
  const body = {};
  // A mask typed or pasted: pairs one a line or joined by ';', or a step list; emptied: none.
  if (maskEdited) body.horizon_mask = $("st-mask").value.trim() || "none";
  const call = $("st-call").value.trim();
  if (call) body.callsign = call;
  const place = $("st-place").value.trim();
  const m = place.match(/^(-?\d+(?:\.\d+)?)\s*[, ]\s*(-?\d+(?:\.\d+)?)$/);
  if (m) { body.lat_deg = Number(m[1]); body.lon_deg = Number(m[2]); } else if (place) body.locator = place;
  const h = $("st-height").value.trim();
  if (h) body.height_m = Number(h);
  if (await post("/api/v1/station", body, "station-reply")) maskEdited = false;
}
async function clearMask() {
  if (await post("/api/v1/station", { horizon_mask: "none" }, "station-reply")) maskEdited = false;
}

// A tap that would take the antenna and radio off a pass in progress asks first.
let lastStatus = null, lastSky = null;
function confirmLeave(name) {
  const f = lastStatus && lastStatus.tracking ? lastStatus.tracking.followed : null;
  const up = lastSky && lastSky.satellite && lastSky.satellite.in_range;
  if (!f || !up || f === name) return true;
  return window.confirm(f + " is passing now. Leave its pass" + (name ? " for " + name : "") + "?");
}

let doppler = true, rotorOn = false;
function drawStatus(st) {
  lastStatus = st;
  if (typeof planList === "function") planList(st);
  if (typeof logSats === "function") logSats(st);
  drawStation(st);
  drawMask(st.station && st.station.horizon_mask);
  $("clock").textContent = st.time ? st.time.substring(0, 10) + " " + clockText(st.time) + " " + zoneName() : "--";
  if (zoneUtc || !st.time) $("clock").textContent = st.time ? st.time.replace("T", " ").substring(0, 19) + " UTC" : "--";
  const probs = st.problems || [];
  $("problems").hidden = probs.length === 0;
  $("problems").replaceChildren(...probs.map((p) => { const li = document.createElement("li"); li.textContent = p; return li; }));
  const a = st.antenna || {};
  $("ant-az").textContent = a.position ? fixed(a.position.az_deg, 1) : "-";
  $("ant-el").textContent = a.position ? fixed(a.position.el_deg, 1) : "-";
  $("ant-target").textContent = a.target ? fixed(a.target.az_deg, 1) + "° az, " + fixed(a.target.el_deg, 1) + "° el" : "-";
  // When the antenna will move for the coming pass (it pre-positions a few minutes before AOS).
  const mv = lastSky && lastSky.moves;
  const moves = mv ? "· moves to " + fixed(mv.az_deg, 0) + "° at " + clockText(mv.at, st.time) + " " + zoneName() +
                     ", " + mv.lead_min + " min before AOS" : "";
  $("ant-state").textContent = a.link !== "ok" ? "fault: " + (a.link_message || a.link)
    : (moves || "(" + (a.action || "hold") + ")" + (a.parking_enabled === false && a.action === "hold" ? ", parking is off" : "")) +
      (a.message ? " " + a.message : "") + (a.follows ? " · " + a.follows : "");
  $("btn-park").hidden = a.parking_enabled === false;
  const k = a.sky_calibration;
  $("ant-offsets").textContent = !k ? "-" : (k.az_offset_deg >= 0 ? "+" : "") + fixed(k.az_offset_deg, 2) + "° az, " +
    (k.el_offset_deg >= 0 ? "+" : "") + fixed(k.el_offset_deg, 2) + "° el" + (k.source ? " (" + k.source + ", " + k.time + ")" : "");
  const pass = lastSky && lastSky.pass;
  $("ant-plan").textContent = planText(pass, a);
  rotorOn = !!a.rotor_control;
  $("rotor-control").textContent = rotorOn ? "on" : "off";
  $("btn-rotor").textContent = rotorOn ? "Rotor control off" : "Rotor control on";
  $("btn-rotor").classList.toggle("on", rotorOn);
  const r = (st.radios || [])[0] || {};
  $("radio-down").textContent = mhz(r.downlink_hz) + (r.downlink_mode ? " " + r.downlink_mode : "");
  $("radio-up").textContent = mhz(r.uplink_hz) + (r.uplink_mode ? " " + r.uplink_mode : "");
  $("radio-state").textContent = r.fault ? "fault: " + r.message : (r.radio || "-") + (r.connected ? ", connected" : "");
  // The receiver records the pass (--record): a REC badge, its file (or why not) on hover.
  const rec = r.recording || {};
  $("radio-rec").hidden = !rec.state || rec.state === "off";
  $("radio-rec").title = (rec.satellite ? rec.satellite + " " : "") + (rec.file || rec.state || "");
  const lk = r.links || {};
  const linkText = (l) => !l ? "-" : l.state + (l.message ? ": " + l.message : "");
  $("link-down").textContent = linkText(lk.downlink);
  $("link-up").textContent = linkText(lk.uplink);
  const c = r.correction;
  $("radio-corr").textContent = !c ? "-" : (c.hz > 0 ? "+" : "") + c.hz + " Hz" +
    (c.key ? " (" + c.key + (c.remembered ? ", kept" : "") + ")" : "") + (c.dial_follow ? ", dial follow" : "");
  drawTuning(r.tuning);
  doppler = st.doppler !== false;
  $("doppler").textContent = doppler ? "on" : "off";
  $("btn-doppler").textContent = doppler ? "Doppler off" : "Doppler on";
  $("btn-doppler").classList.toggle("on", doppler);
  const s = st.station;
  if (s) {
    $("station-pos").textContent = fixed(s.lat_deg, 4) + "°, " + fixed(s.lon_deg, 4) + "°, " + fixed(s.height_m, 0) + " m";
    $("station-loc").textContent = locator(s.lat_deg, s.lon_deg);
  }
  const g = st.gps;
  $("gps").textContent = g ? g.text || g.link : "none";
  $("clock-gps").textContent = g && typeof g.clock_error_s === "number" ? fixed(g.clock_error_s, 2) + " s from GPS time"
                                                                         : "no GPS time";
  drawList(st);
}

// The tuning of the satellite the radio follows (status: radios[0].tuning): each link's spot in the
// satellite's frame, its Doppler, the operator's offset and the dial it gives; a linear transponder's
// passband position moved by the step or the slider (POST /api/v1/radio {"spot_hz"}).
let tuning = null;
function drawTuning(t) {
  tuning = t || null;
  $("tuning").hidden = !t;
  if (!t) return;
  setText("tune-sat", t.satellite);
  drawModes(t);
  // An FM satellite's RX offset is the Offset column's, not the spot's (issue 60: shown in both): the
  // spot of a satellite without a passband is its frequency; a transponder's spot is where it is.
  setText("tune-spot-down", mhz6(t.passband || typeof t.rx_offset_hz !== "number" ? t.downlink_spot_hz
                                                                                  : t.downlink_spot_hz - t.rx_offset_hz));
  setText("tune-spot-up", mhz6(t.uplink_spot_hz));
  setText("tune-dop-down", t.downlink_spot_hz ? signedHz(t.downlink_doppler_hz) : "-");
  setText("tune-dop-up", t.uplink_spot_hz ? signedHz(t.uplink_doppler_hz) : "-");
  setText("tune-rx", signedHz(t.rx_offset_hz));
  setText("tune-tx", signedHz(t.tx_offset_hz));
  setText("tune-dial-down", mhz6(t.downlink_dial_hz));
  setText("tune-dial-up", mhz6(t.uplink_dial_hz));
  setText("tune-tone", (typeof t.tone_hz === "number" ? t.tone_hz.toFixed(1) + " Hz" : "none") +
          (typeof t.arm_tone_hz === "number" ? " (arm with " + t.arm_tone_hz.toFixed(1) + " Hz first)" : ""));
  const pb = t.passband;
  $("passband").hidden = !pb;
  if (!pb) return;
  const sl = $("pb-slider");
  if (sl.min !== String(pb.downlink[0])) { sl.min = pb.downlink[0]; sl.max = pb.downlink[1]; sl.step = 10; }
  if (document.activeElement !== sl) sl.value = t.downlink_spot_hz;
  setText("pb-range", "down " + mhz6(pb.downlink[0]) + "-" + mhz6(pb.downlink[1]) + ", up " + mhz6(pb.uplink[0]) + "-" +
          mhz6(pb.uplink[1]) + (pb.inverting ? " (inverting)" : ""));
}
// The satellite's modes beside its name, the chosen one pressed: one tap chooses another (POST
// /api/v1/radio {"mode"}); the radio goes to its spot with Doppler, tone and link modes.
function drawModes(t) {
  const box = $("tune-modes");
  const modes = Array.isArray(t.modes) ? t.modes : [];
  const key = modes.join("\n") + "|" + t.mode;
  if (box.dataset.key === key) return;
  box.dataset.key = key;
  box.replaceChildren();
  if (modes.length < 2) return;
  for (const m of modes) {
    const b = document.createElement("button");
    b.type = "button";
    b.textContent = m;
    b.setAttribute("aria-pressed", m === t.mode ? "true" : "false");
    b.addEventListener("click", () => tune({ mode: m }));
    box.appendChild(b);
  }
}
function tuneStep() { return Number($("tune-step").value) || 1000; }
function moveSpot(dir) {
  if (!tuning || !tuning.passband) return;
  const [lo, hi] = tuning.passband.downlink;
  tune({ spot_hz: Math.min(hi, Math.max(lo, tuning.downlink_spot_hz + dir * tuneStep())) });
}
function moveOffset(key, dir) {
  if (!tuning) return;
  tune({ [key + "_offset_hz"]: tuning[key + "_offset_hz"] + dir * tuneStep() });
}
function wireTuning() {
  const step = localStorage.getItem("trakbox-step");
  if (step) $("tune-step").value = step;
  $("tune-step").addEventListener("change", () => localStorage.setItem("trakbox-step", $("tune-step").value));
  $("pb-down").addEventListener("click", () => moveSpot(-1));
  $("pb-up").addEventListener("click", () => moveSpot(1));
  $("pb-slider").addEventListener("change", () => tune({ spot_hz: Number($("pb-slider").value) }));
  $("rx-down").addEventListener("click", () => moveOffset("rx", -1));
  $("rx-up").addEventListener("click", () => moveOffset("rx", 1));
  $("tx-down").addEventListener("click", () => moveOffset("tx", -1));
  $("tx-up").addEventListener("click", () => moveOffset("tx", 1));
  $("btn-offsets-reset").addEventListener("click", () => tune({ rx_offset_hz: 0, tx_offset_hz: 0 }));
}

function locator(lat, lon) {
  const A = "ABCDEFGHIJKLMNOPQRSTUVWX";
  let x = lon + 180, y = lat + 90;
  const f = A[Math.floor(x / 20)] + A[Math.floor(y / 10)];
  x %= 20; y %= 10;
  const sq = String(Math.floor(x / 2)) + String(Math.floor(y));
  x %= 2; y %= 1;
  return f + sq + A[Math.floor(x * 12)].toLowerCase() + A[Math.floor(y * 24)].toLowerCase();
}

const PROBLEMS = ["link-lost", "save-failed"];
function addEvent(e, atTop) {
  const li = document.createElement("li");
  li.textContent = (e.time ? clockText(e.time) + " " : "") + (e.event || e.kind) + (e.satellite ? " " + e.satellite : "") +
                   (e.detail ? ": " + e.detail : "");
  if (PROBLEMS.includes(e.event || e.kind)) li.className = "problem";
  const list = $("events");
  if (li.className === "problem" || atTop) list.prepend(li); else {
    const firstPlain = [...list.children].find((c) => c.className !== "problem");
    list.insertBefore(li, firstPlain || null);
  }
  while (list.children.length > 100) list.lastChild.remove();
}

// A change asked of the station; its answer (the note, or why not) is shown under the buttons
// that asked (`where`: the tuning card's own line for the tuning buttons, issue 60).
async function post(path, body, where = "reply") {
  const said = $(where);
  said.textContent = "…";
  try {
    const res = await fetch(path, { method: "POST", headers: { "Content-Type": "application/json" },
                                    body: JSON.stringify(body), credentials: "same-origin" });
    const j = await res.json();
    if (res.status === 401) { location.href = "/login"; return; }
    said.textContent = res.ok ? j.note : j.error;
    return res.ok;
  } catch (e) {
    said.textContent = "the station does not answer";
    return false;
  }
}
function tune(body) { return post("/api/v1/radio", body, "tune-reply"); }

// A station that stops answering is shown so: every value greyed, "station not answering since"
// the time of the last state heard, the buttons disabled, until a state comes again.
let lastHeard = 0, isStale = true;
function heard() {
  lastHeard = Date.now();
  if (!isStale) return;
  isStale = false;
  document.body.classList.remove("stale");
  $("link").textContent = "live";
  $("link").className = "";
  for (const b of document.querySelectorAll("button:not(.keep), input, select")) b.disabled = false;
  if (typeof planChosen === "function") planChosen();
}
function stale() {
  if (isStale && lastHeard) return;
  isStale = true;
  document.body.classList.add("stale");
  $("link").textContent = lastHeard ? "station not answering since " + clockText(new Date(lastHeard).toISOString()) + " " + zoneName()
                                    : "connecting";
  $("link").className = "bad";
  for (const b of document.querySelectorAll("button:not(.keep), input, select")) b.disabled = true;
}
setInterval(() => { if (!isStale && Date.now() - lastHeard > 3000) stale(); }, 1000);

let ws = null, wait = 500;
function connect() {
  const proto = location.protocol === "https:" ? "wss:" : "ws:";
  ws = new WebSocket(proto + "//" + location.host + "/api/v1/live");
  ws.onopen = () => { wait = 500; };
  ws.onmessage = (m) => {
    let j;
    try { j = JSON.parse(m.data); } catch (e) { return; }
    if ((j = liveMessage(j, ws)) === null) return;  // live.js: patches made whole, gaps asked again
    if (j.type === "state") { heard(); lastSky = j.sky; drawStatus(j.status); drawSky(j.sky); drawControl(j.status); }
    else if (j.type === "event") addEvent(j.event, false);
    else if (j.type === "events") { $("events").replaceChildren(); (j.events || []).forEach((e) => addEvent(e, true)); }
  };
  ws.onclose = () => {
    stale();
    setTimeout(start, wait);
    wait = Math.min(wait * 2, 4000);
  };
}

async function start() {
  // Viewing may need the login: ask first, so that a refused feed goes to the login page.
  try {
    const res = await fetch("/api/v1/status", { credentials: "same-origin" });
    if (res.status === 401) { location.href = "/login"; return; }
  } catch (e) {
    stale();
    setTimeout(start, wait);
    wait = Math.min(wait * 2, 4000);
    return;
  }
  connect();
}

// The red night theme (dark adaptation at the rig), remembered; otherwise the system's light or dark.
function night(on) {
  document.body.classList.toggle("night", on);
  $("btn-night").setAttribute("aria-pressed", on ? "true" : "false");
  localStorage.setItem("trakbox-theme", on ? "night" : "");
}
night(localStorage.getItem("trakbox-theme") === "night");
// The zone button: UTC or local for every time shown, kept in this browser; the shown times redrawn.
function zone(utc) {
  zoneUtc = utc;
  localStorage.setItem("trakbox-zone", utc ? "utc" : "local");
  $("btn-zone").textContent = utc ? "UTC" : "Local";
  $("btn-zone").setAttribute("aria-pressed", utc ? "true" : "false");
  $("list-aos").textContent = "AOS (" + zoneName() + ")";
  if (lastStatus) drawStatus(lastStatus);
  if (lastSky) drawSky(lastSky);
  if (typeof planZone === "function") planZone();
  if (typeof logZone === "function") logZone();
}
zone(zoneUtc);
$("btn-zone").addEventListener("click", () => zone(!zoneUtc));
$("station-form").addEventListener("submit", setStation);
// From the first touch of the field the operator's text is kept, not refreshed from the station.
for (const ev of ["focus", "input"]) $("st-mask").addEventListener(ev, () => { maskEdited = true; });
$("btn-mask-none").addEventListener("click", clearMask);
$("btn-night").addEventListener("click", () => night(!document.body.classList.contains("night")));
stale();
drawGrid();
wireTuning();
$("btn-rotor").addEventListener("click", () => post("/api/v1/rotor", { control: !rotorOn }));
$("btn-stop").addEventListener("click", () => post("/api/v1/rotor", { action: "stop" }));
$("btn-park").addEventListener("click", () => post("/api/v1/rotor", { action: "park" }));
$("btn-cal-sun").addEventListener("click", () => post("/api/v1/calibrate", { body: "sun" }));
$("btn-cal-moon").addEventListener("click", () => post("/api/v1/calibrate", { body: "moon" }));
$("btn-cal-undo").addEventListener("click", () => post("/api/v1/calibrate", { undo: true }));
$("btn-doppler").addEventListener("click", () => post("/api/v1/radio", { doppler: !doppler }));
$("btn-multi").addEventListener("click", chooseMulti);  // control.js: asks which satellites
$("btn-refresh").addEventListener("click", () => post("/api/v1/elements/refresh", {}));
start();
