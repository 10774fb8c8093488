"use strict";
// The live state kept whole on the page: the WebSocket sends the whole document once
// ({"type":"state","seq":N,...}) and then only what changed ({"type":"patch","seq":N,"patch":{...}},
// a JSON merge patch, RFC 7386). A patch whose number does not follow the last one means a message
// was missed: the page asks for the whole document ({"type":"full"}) and draws nothing until it comes.
const live = { doc: null, seq: null, asked: false };

// RFC 7386 section 2: the patch applied to the target (objects merged, null removes, the rest replaces).
function mergePatch(target, patch) {
  if (patch === null || typeof patch !== "object" || Array.isArray(patch)) return patch;
  const out = target !== null && typeof target === "object" && !Array.isArray(target) ? target : {};
  for (const k of Object.keys(patch)) {
    if (patch[k] === null) delete out[k];
    else out[k] = mergePatch(out[k], patch[k]);
  }
  return out;
}

// The state as app.js draws it: the tracking list, the radios and the satellites followed, sent as
// objects of their entries by position (so that a patch carries only the entries that changed), made
// lists again.
function asList(v) {
  if (!v || typeof v !== "object" || Array.isArray(v)) return v;
  return Object.keys(v).sort((a, b) => a - b).map((k) => v[k]);
}
function drawable(doc) {
  const st = doc.status;
  if (!st) return doc;
  const out = Object.assign({}, st, { tracking_list: asList(st.tracking_list), radios: asList(st.radios) });
  if (st.tracking && typeof st.tracking === "object")
    out.tracking = Object.assign({}, st.tracking, { satellites: asList(st.tracking.satellites) });
  return Object.assign({}, doc, { status: out });
}

// The message as the page draws it: a state stays a state, a patch becomes the whole state it makes;
// null when the page has no whole state to patch (it has asked for one).
function liveMessage(j, socket) {
  if (j.type === "state") {
    live.doc = j;
    live.seq = typeof j.seq === "number" ? j.seq : null;
    live.asked = false;
    return drawable(j);
  }
  if (j.type !== "patch") return j;
  if (live.doc === null || live.seq === null || j.seq !== live.seq + 1) {
    live.doc = null;
    if (!live.asked && socket && socket.readyState === 1) socket.send(JSON.stringify({ type: "full" }));
    live.asked = true;
    return null;
  }
  live.seq = j.seq;
  live.doc = mergePatch(live.doc, j.patch);
  return drawable(live.doc);
}
