#include "tracker/control.h"

#include <algorithm>
#include <array>

namespace tb::tracker {

namespace {

constexpr std::array<std::string_view, 10> kKindNames = {"tracking", "menus",  "web",     "host",       "rotctld",
                                                         "rigctld",  "satrak", "satnogs", "pstrotator", "standby"};

Holder tracking_holder(orbit::UtcTime now) { return Holder{HolderKind::tracking, "trakbox tracking", now, {}}; }

// The holder a reservation's window puts on a resource when trakbox's own tracking yields to it.
Holder window_holder(const Window& w) {
  Holder h;
  if (w.kind == "satnogs") {
    h.kind = HolderKind::satnogs;
    h.label = "SatNOGS observation " + w.id + (w.satellite.empty() ? "" : " " + w.satellite);
  } else {
    h.kind = HolderKind::menus;
    h.label = "reserved by the operator" + (w.note.empty() ? "" : ": " + w.note);
  }
  h.since = w.start;
  h.until = w.end;
  return h;
}

}  // namespace

std::string_view kind_name(HolderKind k) { return kKindNames[static_cast<std::size_t>(k)]; }

std::optional<HolderKind> kind_named(std::string_view word) {
  for (std::size_t i = 0; i < kKindNames.size(); ++i)
    if (kKindNames[i] == word) return static_cast<HolderKind>(i);
  return std::nullopt;
}

bool is_operator(HolderKind k) { return k == HolderKind::menus || k == HolderKind::web || k == HolderKind::host; }

bool is_outside(HolderKind k) {
  return k == HolderKind::rotctld || k == HolderKind::rigctld || k == HolderKind::satrak ||
         k == HolderKind::satnogs || k == HolderKind::pstrotator;
}

std::string_view resource_name(Resource r) { return r == Resource::antenna ? "antenna" : "radio"; }

std::optional<Change> Control::hand_to(Resource r, Holder h, std::string why) {
  Slot& s = slot(r);
  if (s.now.kind == h.kind && s.now.label == h.label && s.now.until == h.until) return std::nullopt;
  Change c{r, s.now, h, std::move(why)};
  s.now = std::move(h);
  return c;
}

std::optional<Change> Control::hand_back(Resource r, orbit::UtcTime now, std::string why) {
  Slot& s = slot(r);
  Holder next = s.before.value_or(tracking_holder(now));
  next.since = now;
  // A window that has ended holds nothing any more.
  if (next.until && *next.until <= now) next = tracking_holder(now);
  s.before.reset();
  s.client.clear();
  return hand_to(r, std::move(next), std::move(why));
}

Control::Answer Control::request(Resource r, const Requester& who, orbit::UtcTime now, bool confirmed,
                                 bool to_tracking) {
  Answer a;
  Slot& s = slot(r);
  const Holder& h = s.now;
  const std::string what = r == Resource::antenna ? "the antenna" : "the radio";
  if (h.kind == HolderKind::standby) {
    a.refusal = is_outside(who.kind) ? "the station is in standby: " + what + " is not available"
                                     : "the station is in standby: turn standby off first";
    return a;
  }
  if (is_outside(who.kind)) {
    if (!s.client.empty() && s.client == who.label) {  // the holder again
      s.last_heard = now;
      a.granted = true;
      return a;
    }
    // The operator took it back from an outside client: it stays the operator's (trakbox's tracking)
    // until --handback (30 s when 0) has passed since the operator's last action (issue 60).
    if (s.operator_took) {
      const auto guard = std::chrono::seconds(settings_.handback_s > 0 ? settings_.handback_s : kOperatorGuardS);
      if (now - *s.operator_took < guard)
        return Answer{false, "the operator took " + what + " back; outside clients may move it again " +
                                 std::to_string(std::chrono::duration_cast<std::chrono::seconds>(
                                                    guard - (now - *s.operator_took)).count()) +
                                 " s after the operator's last action", {}, {}};
      s.operator_took.reset();
    }
    if (settings_.exclusive && !s.client.empty() && is_outside(h.kind) && h.kind != HolderKind::satnogs &&
        *settings_.exclusive == h.kind)
      return Answer{false, h.label + " holds " + what + " (--exclusive " + std::string(kind_name(h.kind)) + ")", {}, {}};
    if (settings_.exclusive && !s.client.empty() && h.kind == HolderKind::satnogs &&
        s.client.rfind(std::string(kind_name(*settings_.exclusive)), 0) == 0)
      return Answer{false, s.client + " holds " + what + " (--exclusive " +
                               std::string(kind_name(*settings_.exclusive)) + ")", {}, {}};
    Holder next{who.kind, who.label, now, {}};
    if (const Window* w = window_at(now); w && w->kind == "satnogs") {
      next = window_holder(*w);  // the SatNOGS client works under its observation's name
      next.label += " (" + who.label + ")";
      next.since = now;
    }
    if (s.client.empty()) s.before = h;  // trakbox's tracking, the operator or a window: it holds again after
    s.client = who.label;
    s.last_heard = now;
    if (auto c = hand_to(r, std::move(next), who.label + (r == Resource::antenna ? " moved the antenna" : " tuned the radio")))
      a.changes.push_back(std::move(*c));
    a.granted = true;
    return a;
  }
  // The operator (or trakbox itself): always, after one confirmation from an outside holder or a window.
  const bool taken_from_outside = is_outside(h.kind) || (h.until && *h.until > now && h.kind != who.kind);
  if (taken_from_outside && !confirmed && is_operator(who.kind)) {
    a.confirm = h;
    return a;
  }
  if (is_operator(who.kind) && (is_outside(h.kind) || s.operator_took)) s.operator_took = now;
  Holder next = to_tracking ? tracking_holder(now) : Holder{who.kind, who.label, now, {}};
  s.before.reset();
  s.client.clear();
  if (auto c = hand_to(r, std::move(next), to_tracking ? who.label + " chose what to track" : who.label + " took it"))
    a.changes.push_back(std::move(*c));
  a.granted = true;
  return a;
}

void Control::heard(std::string_view label, orbit::UtcTime now) {
  for (Slot* s : {&antenna_, &radio_})
    if (!s->client.empty() && s->client == label) s->last_heard = now;
}

std::vector<Change> Control::left(std::string_view label, orbit::UtcTime now) {
  std::vector<Change> out;
  for (const Resource r : {Resource::antenna, Resource::radio})
    if (!slot(r).client.empty() && slot(r).client == label)
      if (auto c = hand_back(r, now, std::string(label) + " disconnected")) out.push_back(std::move(*c));
  return out;
}

std::vector<Change> Control::tick(orbit::UtcTime now) {
  std::vector<Change> out;
  for (const Resource r : {Resource::antenna, Resource::radio}) {
    Slot& s = slot(r);
    // Held by trakbox's tracking since the station started: the first tick's time, not 1970 (issue 60).
    if (s.now.since == orbit::UtcTime{}) s.now.since = now;
    // A connectionless sender (PstRotator's UDP) never disconnects: its silence ends its hold even
    // under --handback 0, after kConnectionlessHandbackS (issue 56).
    const bool connectionless = s.now.kind == HolderKind::pstrotator;
    const int after = settings_.handback_s > 0 ? settings_.handback_s : connectionless ? kConnectionlessHandbackS : 0;
    if (s.client.empty() || after <= 0) continue;
    if (now - s.last_heard >= std::chrono::seconds(after))
      if (auto c = hand_back(r, now, s.client + " silent " + std::to_string(after) + " s"))
        out.push_back(std::move(*c));
  }
  for (Change& c : windows_tick(now)) out.push_back(std::move(c));
  return out;
}

std::vector<Change> Control::windows_tick(orbit::UtcTime now) {
  std::vector<Change> out;
  const Window* w = window_at(now);
  // The window that took a resource is no longer booked (a SatNOGS job cancelled or deleted, a
  // reservation removed): its hold ends now, not at its old end.
  auto cancelled = [this](const std::string& yielded) {
    if (yielded.empty()) return false;
    for (const Window& x : windows_)
      if (x.id + x.kind == yielded) return false;
    return true;
  };
  for (const Resource r : {Resource::antenna, Resource::radio}) {
    Slot& s = slot(r);
    if (s.client.empty() && s.now.until && *s.now.until > now && cancelled(s.yielded))
      if (auto c = hand_back(r, now, "its window was cancelled")) out.push_back(std::move(*c));
    if (s.before && s.before->until && cancelled(s.yielded)) s.before.reset();
    // A window's own hold (no client) ends with it; a client's under it ends by its own rules.
    if (s.client.empty() && s.now.until && *s.now.until <= now)
      if (auto c = hand_back(r, now, "the reservation ended")) out.push_back(std::move(*c));
    if (s.client.empty() && s.before && s.before->until && *s.before->until <= now) s.before.reset();
    if (!w || s.yielded == w->id + w->kind) continue;
    s.yielded = w->id + w->kind;  // once: the operator may take it back for the rest of the window
    if (s.now.kind != HolderKind::tracking) continue;
    if (auto c = hand_to(r, window_holder(*w), "the reservation began")) out.push_back(std::move(*c));
  }
  return out;
}

std::vector<Change> Control::set_standby(bool on, orbit::UtcTime now) {
  std::vector<Change> out;
  for (const Resource r : {Resource::antenna, Resource::radio}) {
    Slot& s = slot(r);
    s.before.reset();
    s.client.clear();
    const Holder h = on ? Holder{HolderKind::standby, "standby", now, {}} : tracking_holder(now);
    if (!on && s.now.kind != HolderKind::standby) continue;
    if (auto c = hand_to(r, h, on ? "standby on" : "standby off")) out.push_back(std::move(*c));
  }
  return out;
}

void Control::set_windows(std::vector<Window> w) {
  std::sort(w.begin(), w.end(), [](const Window& a, const Window& b) { return a.start < b.start; });
  windows_ = std::move(w);
}

const Window* Control::window_at(orbit::UtcTime now) const {
  for (const Window& w : windows_)
    if (w.start <= now && now < w.end) return &w;
  return nullptr;
}

std::string held_text(const Control& c) {
  if (c.standby()) return "STANDBY";
  std::string out;
  for (const Resource r : {Resource::antenna, Resource::radio}) {
    const Holder& h = c.holder(r);
    if (h.kind == HolderKind::tracking) continue;
    out += (out.empty() ? "" : ", ") + std::string(resource_name(r)) + " " + h.label;
  }
  return out;
}

}  // namespace tb::tracker
