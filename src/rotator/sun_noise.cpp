// The expected Sun noise (rotator/sun_noise.h).
#include "rotator/sun_noise.h"

#include <cmath>
#include <numbers>

#include "util/format.h"

namespace tb::rotator {
namespace {
constexpr double kBoltzmann = 1.380649e-23;          // J/K (SI, exact)
constexpr double kSpeedOfLightMS = 299792458.0;
constexpr double kSfu = 1e-22;                         // W m^-2 Hz^-1
}  // namespace

FluxEstimate solar_flux_at(std::span<const FluxPoint> measured, double freq_mhz) {
  FluxEstimate e;
  if (measured.empty()) {
    e.error = "no measured solar flux";
    return e;
  }
  for (std::size_t i = 0; i < measured.size(); ++i) {
    const FluxPoint& p = measured[i];
    if (!(p.sfu > 0.0) || !(p.freq_mhz > 0.0) || !std::isfinite(p.sfu) || !std::isfinite(p.freq_mhz)) {
      e.error = text::printf_string("flux point %zu (%g MHz, %g SFU) is not a positive number", i + 1,
                                    p.freq_mhz, p.sfu);
      return e;
    }
    if (i > 0 && !(p.freq_mhz > measured[i - 1].freq_mhz)) {
      e.error = text::printf_string("flux point %zu (%g MHz) does not follow %g MHz in rising frequency", i + 1,
                                    p.freq_mhz, measured[i - 1].freq_mhz);
      return e;
    }
  }
  if (!(freq_mhz >= measured.front().freq_mhz && freq_mhz <= measured.back().freq_mhz)) {
    e.error = text::printf_string("%g MHz is outside the measured %g..%g MHz", freq_mhz,
                                  measured.front().freq_mhz, measured.back().freq_mhz);
    return e;
  }
  for (std::size_t i = 1; i < measured.size(); ++i) {
    const FluxPoint& lo = measured[i - 1];
    const FluxPoint& hi = measured[i];
    if (freq_mhz > hi.freq_mhz) continue;
    if (freq_mhz == lo.freq_mhz || freq_mhz == hi.freq_mhz) {  // a measured frequency: its own value
      e.sfu = freq_mhz == lo.freq_mhz ? lo.sfu : hi.sfu;
      return e;
    }
    const double f = std::log(freq_mhz / lo.freq_mhz) / std::log(hi.freq_mhz / lo.freq_mhz);
    e.sfu = std::exp(std::log(lo.sfu) + f * std::log(hi.sfu / lo.sfu));
    return e;
  }
  e.sfu = measured.front().sfu;  // a single point, asked at its own frequency
  return e;
}

double sun_antenna_temperature_k(double flux_sfu, double gain_dbi, double freq_hz) {
  const double gain = std::pow(10.0, gain_dbi / 10.0);
  const double lambda = kSpeedOfLightMS / freq_hz;
  return flux_sfu * kSfu * gain * lambda * lambda / (8.0 * std::numbers::pi * kBoltzmann);
}

double system_temperature_k(double nf_db, double sky_k) {
  return (std::pow(10.0, nf_db / 10.0) - 1.0) * 290.0 + sky_k;
}

double sun_noise_y_db(double antenna_k, double system_k) {
  return 10.0 * std::log10((antenna_k + system_k) / system_k);
}

}  // namespace tb::rotator
