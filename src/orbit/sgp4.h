// SGP4/SDP4 (Vallado, Crawford, Hujsak, Kelso, "Revisiting Spacetrack Report #3", AIAA 2006-6753),
// WGS-72 constants, improved mode. Written for this project from the published algorithm.
// Results are in the TEME frame, km and km/s. A failure is a value, never an exception.
#pragma once
#include <array>
#include <memory>
#include <optional>

#include "orbit/elements.h"

namespace tb::orbit {

// Vallado's error codes.
enum class Sgp4Error : int {
  none = 0,
  mean_eccentricity = 1,       // mean eccentricity out of range [0, 1) (or < -0.001)
  mean_motion = 2,             // mean motion < 0
  perturbed_eccentricity = 3,  // perturbed eccentricity out of range
  semi_latus_rectum = 4,       // semi-latus rectum < 0
  decayed = 6,                 // orbit has decayed (radius < 1 earth radius)
};
const char* describe(Sgp4Error e);

using Vec3 = std::array<double, 3>;

struct StateVector {
  Vec3 r_km{};      // TEME position
  Vec3 v_km_s{};    // TEME velocity
};

struct Propagation {
  Sgp4Error error = Sgp4Error::none;
  StateVector state;           // valid only when error == none
  bool ok() const { return error == Sgp4Error::none; }
};

// The coefficients of a near-earth (SGP4, not SDP4) model that a propagation reads: what the
// vectorised batch kernel (sgp4_batch.h) takes. Names as in Vallado's satrec.
struct NearEarthTerms {
  double ecco, inclo, nodeo, argpo, mo, no_unkozai, bstar, sinio, cosio, ao;
  double mdot, argpdot, nodedot;
  double cc1, cc4, cc5, d2, d3, d4, delmo, eta, omgcof, sinmao, t2cof, t3cof, t4cof, t5cof, xmcof, nodecf;
  double aycof, xlcof, con41, x1mth2, x7thm1;
  bool simplified_drag;
};

// A propagation halfway: the elements after the secular, drag, deep-space and lunar-solar terms, and
// the coefficients that depend on the perturbed inclination. The rest (long-period periodics,
// Kepler's equation, short-period periodics) depends on nothing else, so the batch kernel runs it
// vectorised for deep-space sets too (sgp4_batch.h). Names as in Vallado's sgp4().
struct PerturbedTerms {
  double am, nm, ep, nodep, argpp, mp, sinip, cosip;
  double aycof, xlcof, con41, x1mth2, x7thm1;
  Sgp4Error error;  // when not none, a propagation fails with it and nothing above is valid
};

namespace detail {
class Sgp4Access;
}

class Sgp4 {
 public:
  explicit Sgp4(const Elements& elements);

  // Error found while initialising (then every propagation returns it too).
  Sgp4Error init_error() const { return init_error_; }
  bool deep_space() const { return deep_space_; }
  const Elements& elements() const { return elements_; }
  JulianDate epoch_jd() const { return epoch_jd_; }
  UtcTime epoch() const { return epoch_; }

  // tsince in minutes from epoch. Thread-safe: const, no hidden cache.
  Propagation propagate_minutes(double tsince) const;
  Propagation propagate(UtcTime t) const { return propagate_minutes(minutes_between(epoch_, t)); }

  // The first half of propagate_minutes(tsince) (PerturbedTerms above).
  PerturbedTerms perturbed_terms(double tsince) const;

  // The near-earth coefficients; nullopt for a deep-space set or one that failed to initialise.
  std::optional<NearEarthTerms> near_earth_terms() const;

  // Un-Kozai'd mean motion (rad/min) and semi-major axis (earth radii) from initialisation.
  double mean_motion_rad_per_min() const;
  double semi_major_axis_er() const;
  double period_minutes() const;
  double perigee_km() const;   // above the WGS-72 equatorial radius
  double apogee_km() const;

 private:
  friend class detail::Sgp4Access;
  struct Model;  // every coefficient Vallado's satrec holds; immutable after construction
  Elements elements_;
  JulianDate epoch_jd_{};
  UtcTime epoch_{};
  Sgp4Error init_error_ = Sgp4Error::none;
  bool deep_space_ = false;
  std::shared_ptr<const Model> model_;  // shared by copies; never mutated
};

// What SGP4 makes of a set at its epoch (none: an orbit it can propagate); the check of a set
// edited by hand (menu 3-1).
inline Sgp4Error error_at_epoch(const Elements& e) { return Sgp4(e).propagate_minutes(0.0).error; }

namespace detail {
// For tests: the same set with the resonance integrator's checkpoints dropped, so that every
// propagation integrates from epoch as the reference does (sgp4.cpp, kCheckpointStride).
Sgp4 without_resonance_checkpoints(const Sgp4& sat);
}  // namespace detail

}  // namespace tb::orbit
