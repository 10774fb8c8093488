// The Sun noise a station should hear: a health check of gain over system temperature (G/T) next
// to the measured one (a sun-noise scan's peak over cold sky, rotator/sun_scan.h). Pure.
//
//   Ta = F * G * lambda^2 / (8 pi k 1e22) = F * G * lambda^2 / 3.4699
//       F: the Sun's flux density at the frequency, solar flux units (1 SFU = 1e-22 W m^-2 Hz^-1),
//          both polarisations (an antenna takes one half: the 2 in S Ae / 2k); G: the antenna's gain
//          as a ratio; lambda in metres. For a beam wider than the Sun's half degree.
//   Y  = (Ta + Tsys) / Tsys, in dB, with Tsys = (NF - 1) * 290 K + Tsky (cold sky) for a receiver
//        of noise factor NF.
// The flux comes from the RSTN observatories' daily values at 245, 410, 610, 1415, 2695, 4995, 8800
// and 15400 MHz (NOAA SWPC's solar-radio-flux.json), interpolated to the operating frequency.
// docs/calibration.md.
#pragma once
#include <optional>
#include <span>
#include <string>

namespace tb::rotator {

// The RSTN frequencies, MHz.
inline constexpr double kRstnFrequenciesMhz[] = {245, 410, 610, 1415, 2695, 4995, 8800, 15400};

struct FluxPoint {
  double freq_mhz = 0.0;
  double sfu = 0.0;
};

struct FluxEstimate {
  double sfu = 0.0;
  std::string error;  // when not empty, no estimate: why
  bool ok() const { return error.empty(); }
};

// The flux at freq_mhz: straight lines between the two measured frequencies either side of it on
// log(flux) against log(frequency) (a power law between neighbours); a measured frequency gives its
// own value. Refused, saying why, when the points are not in rising frequency with positive fluxes,
// or freq_mhz lies outside them (no extrapolation).
FluxEstimate solar_flux_at(std::span<const FluxPoint> measured, double freq_mhz);

// Ta of the Sun, kelvin, for flux_sfu, an antenna gain in dBi and a frequency in Hz.
double sun_antenna_temperature_k(double flux_sfu, double gain_dbi, double freq_hz);
// Tsys, kelvin, of a receiver with noise figure nf_db looking at cold sky of sky_k.
double system_temperature_k(double nf_db, double sky_k);
// The Sun's noise over cold sky, dB: 10 log10((Ta + Tsys) / Tsys).
double sun_noise_y_db(double antenna_k, double system_k);

}  // namespace tb::rotator
