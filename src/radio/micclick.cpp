#include "radio/micclick.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "radio/simulated.h"

namespace tb::radio {

const char* to_string(Pulse p) { return p == Pulse::up ? "UP" : "DOWN"; }

void SimulatedPulseOutput::pulse(Pulse p) {
  pulses_.push_back(p);
  if (radio_) radio_->step(Link::downlink, p == Pulse::up ? step_hz_ : -step_hz_);
}

int SimulatedPulseOutput::net_steps() const {
  int n = 0;
  for (Pulse p : pulses_) n += p == Pulse::up ? 1 : -1;
  return n;
}

int SimulatedDiscriminator::read(Hz signal, Hz radio) const {
  const Hz residual = signal - radio;   // + : the signal is above where the radio listens
  if (residual > capture_hz || residual < -capture_hz) return centre_adc;
  double v = counts_per_khz * static_cast<double>(residual) / 1000.0;
  if (inverted) v = -v;
  const long adc = std::lround(centre_adc + v);
  return static_cast<int>(std::clamp<long>(adc, 0, kAdcMax));
}

std::string MicClickMeasure::text() const {
  char buf[96];
  std::snprintf(buf, sizeof buf, "ADC3= %4d center %d span %d: %s", adc, adc - error, span,
                locked ? "locked" : (error > 0 ? "above" : "below"));
  return buf;
}

MicClick::MicClick(const MicClickConfig& config, PulseOutput& output) : config_(config), out_(output) {}

std::optional<Pulse> MicClick::decide(int adc) const {
  const int err = adc - config_.centre_adc;
  const int span = config_.span();
  if (err >= -span && err <= span) return std::nullopt;
  Pulse p = err > 0 ? Pulse::up : Pulse::down;
  if (config_.polarity == PulsePolarity::reverse) p = p == Pulse::up ? Pulse::down : Pulse::up;
  return p;
}

std::optional<Pulse> MicClick::step(int adc) {
  auto p = decide(adc);
  if (p) send(*p);
  return p;
}

void MicClick::send(Pulse p) {
  out_.pulse(p);
  net_ += p == Pulse::up ? 1 : -1;
}

int MicClick::pre_correct(Hz correction_hz) {
  if (config_.step_hz <= 0) return 0;
  const long n = std::lround(static_cast<double>(correction_hz) / static_cast<double>(config_.step_hz));
  for (long i = 0; i < std::labs(n); ++i) send(n > 0 ? Pulse::up : Pulse::down);
  return static_cast<int>(n);
}

MicClickMeasure MicClick::measure(int adc) const {
  MicClickMeasure m;
  m.adc = adc;
  m.error = adc - config_.centre_adc;
  m.span = config_.span();
  m.locked = m.error >= -m.span && m.error <= m.span;
  return m;
}

}  // namespace tb::radio
