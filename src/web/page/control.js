"use strict";
// Who holds the antenna and the radio (issue 44, docs/sharing.md): the header names the holder when
// it is not trakbox's own tracking, with "Take back"; the operator confirms before taking it from an
// outside client or a SatNOGS window (the API answers 409 with the holder). Multiple tracking asks
// which satellites (2 to 5). app.js calls drawControl with each state and chooseMulti for its button.
let controlStatus = null;

function holderText(st) {
  const c = st.control;
  if (!c) return "";
  if (st.standby) return "STANDBY";
  const parts = [];
  if (c.antenna && c.antenna.kind !== "tracking") parts.push("antenna: " + c.antenna.label);
  if (c.radio && c.radio.kind !== "tracking") parts.push("radio: " + c.radio.label);
  return parts.join(" · ");
}

function drawControl(st) {
  controlStatus = st;
  const text = holderText(st);
  const box = document.getElementById("holder");
  box.hidden = text === "";
  document.getElementById("holder-text").textContent = text;
  document.getElementById("btn-take").textContent = st.standby ? "Standby off" : "Take back";
}

async function sendControl(path, body) {
  const reply = document.getElementById("reply");
  try {
    let res = await fetch(path, { method: "POST", headers: { "Content-Type": "application/json" },
                                  body: JSON.stringify(body), credentials: "same-origin" });
    let j = await res.json();
    if (res.status === 409 && j.confirm_needed) {
      if (!window.confirm(j.holder.label + " holds it now. Take it back?")) { reply.textContent = "left with " + j.holder.label; return; }
      res = await fetch(path, { method: "POST", headers: { "Content-Type": "application/json" },
                                body: JSON.stringify(Object.assign({}, body, { confirm: true })), credentials: "same-origin" });
      j = await res.json();
    }
    if (res.status === 401) { location.href = "/login"; return; }
    reply.textContent = res.ok ? j.note : j.error;
  } catch (e) {
    reply.textContent = "the station does not answer";
  }
}

function takeBack() {
  if (controlStatus && controlStatus.standby) sendControl("/api/v1/standby", { on: false });
  else sendControl("/api/v1/control", { take_back: true });
}

// Multiple tracking of the satellites the operator names (2 to 5, from the tracking list by default).
function chooseMulti() {
  const list = (controlStatus && controlStatus.tracking_list || []).map((e) => e.name);
  const answer = window.prompt("Multiple tracking: which satellites (2 to 5, separated by commas)?",
                               list.slice(0, 2).join(", "));
  if (answer === null) return;
  const names = answer.split(",").map((s) => s.trim()).filter((s) => s !== "");
  if (names.length < 2 || names.length > 5) {
    document.getElementById("reply").textContent = "multiple tracking takes 2 to 5 satellites; " + names.length + " given";
    return;
  }
  sendControl("/api/v1/track", { list: names });
}

document.getElementById("btn-take").addEventListener("click", takeBack);
