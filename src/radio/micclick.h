// Mic-click Doppler (menu 6-8): a closed loop on the radio's UP/DOWN microphone buttons.
//
// The error voltage of the radio's FM discriminator (9600 bps, UO-22) or PSK modem (1200 bps,
// FO-20, AO-16) is read on ADC3 (0..1023). Each reading is compared with the configured centre
// ("modem locked center ADC value"); when it is off the centre by more than the span
// |reference - centre|, one UP or DOWN pulse goes to the radio, which moves its dial by one
// tuning step (the "Step Frequency" the operator entered). Normal polarity: above the centre ->
// UP; Reverse swaps the pulses (discriminators differ in sign, and so does LSB against USB).
//
// At AOS, with "automatic up pulse generation", the Doppler expected at AOS is pre-corrected with
// round(correction / step) pulses (UP while approaching) so the signal lands inside the loop's
// capture range. With "frequency set CAT command at AOS" the Tuner sets the radio by CAT first
// (doppler.h).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "radio/config.h"

namespace tb::radio {

enum class Pulse { up, down };
const char* to_string(Pulse p);   // "UP" / "DOWN"

inline constexpr int kAdcMax = 1023;

// Where pulses go: the radio's UP/DOWN lines.
class PulseOutput {
 public:
  virtual ~PulseOutput() = default;
  virtual void pulse(Pulse p) = 0;
};

class SimulatedRadio;

// Records every pulse; with a radio attached, each pulse moves its downlink by one step, as a
// radio's UP/DOWN buttons do.
class SimulatedPulseOutput final : public PulseOutput {
 public:
  explicit SimulatedPulseOutput(Hz step_hz = 100, SimulatedRadio* radio = nullptr)
      : step_hz_(step_hz), radio_(radio) {}
  void pulse(Pulse p) override;
  const std::vector<Pulse>& pulses() const { return pulses_; }
  int net_steps() const;   // UP minus DOWN
  void clear() { pulses_.clear(); }

 private:
  Hz step_hz_;
  SimulatedRadio* radio_;
  std::vector<Pulse> pulses_;
};

// A simulated discriminator: its output follows the residual between where the signal is and
// where the radio is tuned, linear inside the capture range and back at the centre (no signal)
// outside it, clamped to the ADC's 0..1023.
struct SimulatedDiscriminator {
  int centre_adc = 550;
  double counts_per_khz = 40.0;   // slope
  Hz capture_hz = 5000;           // beyond this the modem hears nothing
  bool inverted = false;          // a discriminator of the other sign (needs Reverse polarity)

  int read(Hz signal_at_radio_hz, Hz radio_tuned_hz) const;
};

struct MicClickMeasure {
  int adc = 0;
  int error = 0;        // adc - centre
  int span = 0;
  bool locked = false;  // within the span
  // "ADC3=  548 center 550 span 10: locked" (menu 6-8 "Measure")
  std::string text() const;
};

class MicClick {
 public:
  MicClick(const MicClickConfig& config, PulseOutput& output);
  void set_config(const MicClickConfig& config) { config_ = config; }
  const MicClickConfig& config() const { return config_; }

  // One reading of ADC3: at most one pulse, which is sent and returned.
  std::optional<Pulse> step(int adc);
  // The direction step() would choose, without sending.
  std::optional<Pulse> decide(int adc) const;

  // AOS pre-correction: round(correction / step) pulses, UP for a positive correction. Returns the
  // number sent (signed: + UP).
  int pre_correct(Hz correction_hz);

  MicClickMeasure measure(int adc) const;

  // Pulses sent since construction (+ UP, - DOWN) and what they moved the radio.
  int net_pulses() const { return net_; }
  Hz net_correction_hz() const { return net_ * config_.step_hz; }

 private:
  void send(Pulse p);
  MicClickConfig config_;
  PulseOutput& out_;
  int net_ = 0;
};

}  // namespace tb::radio
