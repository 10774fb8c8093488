// The "Log QSO" card (docs/logbook.md): call, grid and report typed at the rig; the station fills
// the satellite, mode, both frequencies and the time from the pass it tracks (POST /api/v1/log).
// Below it the QSOs of the station's UTC day (since=today: its clock, not the browser's) with edit
// (call, grid, reports, note, in the row) and delete, and the ADIF export link.
"use strict";
(function () {
  const el = (id) => document.getElementById(id);

  async function call(method, path, body) {
    const opts = { method, credentials: "same-origin" };
    if (body) { opts.headers = { "Content-Type": "application/json" }; opts.body = JSON.stringify(body); }
    let res, j;
    try {
      res = await fetch(path, opts);
      if (res.status === 401) { location.href = "/login"; return null; }
      j = await res.json();
    } catch (e) {
      throw new Error("the station does not answer");
    }
    if (!res.ok) throw new Error(j.error || ("HTTP " + res.status));
    return j;
  }

  function say(text, bad) {
    const r = el("log-reply");
    r.textContent = text;
    r.className = bad ? "note bad" : "note";
  }

  function button(text, onClick) {
    const b = document.createElement("button");
    b.type = "button";
    b.textContent = text;
    b.addEventListener("click", onClick);
    return b;
  }

  // Edit in place: the row becomes fields for the call, the grid, both reports and the note;
  // Save sends only what changed (POST /api/v1/log/edit), Cancel puts the row back.
  const kEditable = [["call", "Call", 12], ["grid", "Grid", 8], ["rst_sent", "RST sent", 3],
                     ["rst_rcvd", "RST rcvd", 3], ["note", "Note", 24]];
  function edit(q, tr) {
    tr.textContent = "";
    const td = document.createElement("td");
    td.colSpan = 6;
    const form = document.createElement("form");
    form.className = "log-edit";
    const inputs = {};
    for (const [key, label, size] of kEditable) {
      const l = document.createElement("label");
      l.textContent = label + " ";
      const i = document.createElement("input");
      i.value = q[key] || "";
      i.size = size;
      i.autocapitalize = key === "note" ? "sentences" : "characters";
      i.setAttribute("aria-label", label + " of QSO " + q.id);
      inputs[key] = i;
      l.appendChild(i);
      form.appendChild(l);
    }
    const save = button("Save", () => {});
    save.type = "submit";
    form.appendChild(save);
    form.appendChild(button("Cancel", () => refresh(true)));
    form.addEventListener("submit", async (ev) => {
      ev.preventDefault();
      const body = { id: q.id };
      for (const [key] of kEditable) {
        const v = inputs[key].value.trim();
        if (v !== (q[key] || "")) body[key] = v;
      }
      if (Object.keys(body).length === 1) { refresh(true); return; }
      try {
        await call("POST", "/api/v1/log/edit", body);
        say("QSO " + q.id + " changed");
        refresh(true);
      } catch (e) { say(e.message, true); }
    });
    td.appendChild(form);
    tr.appendChild(td);
    inputs.call.focus();
  }

  async function remove(q) {
    if (!confirm("Delete QSO " + q.id + " with " + q.call + "?")) return;
    try {
      await call("POST", "/api/v1/log/delete", { id: q.id });
      say("QSO " + q.id + " deleted");
      refresh();
    } catch (e) { say(e.message, true); }
  }

  // Not while a row is being edited (the list is rebuilt), unless Save or Cancel asks.
  // The list's times in the page's zone (app.js's zone button); the day listed is the station's UTC day.
  // The satellite field: empty logs on the satellite tracked (shown as its placeholder); with none
  // tracked (after LOS in multiple tracking) the operator names it, chosen from the tracking list.
  window.logSats = (st) => {
    const input = el("log-sat");
    if (!input) return;
    const followed = st.tracking && st.tracking.followed;
    const hint = followed || "name the satellite";
    if (input.placeholder !== hint) input.placeholder = hint;
    const names = (st.tracking_list || []).map((e) => e.name).join("\n");
    const list = el("log-sats");
    if (list.dataset.names === names) return;
    list.dataset.names = names;
    list.replaceChildren(...(st.tracking_list || []).map((e) => { const o = document.createElement("option"); o.value = e.name; return o; }));
  };

  window.logZone = () => {
    el("log-zone").textContent = zoneName() === "UTC" ? "UTC" : "Local";
    refresh(true);
  };

  async function refresh(force) {
    if (!force && document.querySelector("#log-list .log-edit")) return;
    let j;
    try { j = await call("GET", "/api/v1/log?since=today"); } catch (e) { say(e.message, true); return; }
    if (!j) return;
    const body = el("log-list").querySelector("tbody");
    body.textContent = "";
    for (const q of j.qsos.slice().reverse()) {
      const tr = document.createElement("tr");
      for (const v of [clockText(q.time_on, null, false), q.call, q.sat_name, q.grid, q.mode]) {
        const td = document.createElement("td");
        td.textContent = v;
        tr.appendChild(td);
      }
      const td = document.createElement("td");
      td.appendChild(button("Edit", () => edit(q, tr)));
      td.appendChild(button("Delete", () => remove(q)));
      tr.appendChild(td);
      body.appendChild(tr);
    }
    // A day of more than a page (500) shows its first page and says there are more.
    el("log-count").textContent = j.qsos.length + (j.next ? "+" : "") + " today, " + j.summary.count + " in the log" +
      (j.summary.queue ? ", " + j.summary.queue + " to upload" : "");
  }

  async function logQso(ev) {
    ev.preventDefault();
    const body = { call: el("log-call").value.trim() };
    const grid = el("log-grid").value.trim(), rst = el("log-rst").value.trim();
    if (grid) body.grid = grid;
    if (rst) body.rst_sent = rst;
    const sat = el("log-sat").value.trim();
    if (sat) body.sat = sat;   // empty: the satellite tracked (after LOS in multiple tracking: name it)
    say("…");
    try {
      const j = await call("POST", "/api/v1/log", body);
      if (!j) return;
      say("Logged " + j.qso.call + " on " + j.qso.sat_name + " " + j.qso.mode + " at " + clockText(j.qso.time_on) + " " + zoneName() +
          (j.warning ? " · " + j.warning : ""), !!j.warning);
      el("log-call").value = "";
      el("log-grid").value = "";
      el("log-call").focus();
      refresh();
    } catch (e) { say(e.message, true); }
  }

  document.addEventListener("DOMContentLoaded", () => {
    if (!el("log-form")) return;
    el("log-form").addEventListener("submit", logQso);
    el("log-zone").textContent = zoneName() === "UTC" ? "UTC" : "Local";
    refresh();
    setInterval(refresh, 60000);
  });
})();
