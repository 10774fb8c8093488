// SGP4 for many times and many element sets at once.
//
// A near-earth set is propagated at many times by a vectorised kernel: the set's coefficients are
// broadcast, the times lie side by side in structure-of-arrays blocks, and the core runs without a
// branch that depends on the time (failures become per-lane error codes, Kepler's iteration runs
// until every lane of a block has converged). On x86-64 the kernel is compiled for AVX-512, AVX2
// and the baseline, and the processor's best is chosen at run time; elsewhere it is portable C++
// that the compiler vectorises for the target's baseline. A deep-space set's secular, resonance and
// lunar-solar terms are computed time by time by Sgp4::perturbed_terms (scalar: the resonance
// integrator starts from a checkpoint that depends on the time), and the rest, most of the cost, by
// the same vectorised long-period, Kepler and short-period stages.
//
// The results agree with Sgp4::propagate_minutes to 1e-9 km and 1e-12 km/s (differences of rounding:
// the order of operations and contracted multiply-adds differ); error codes are the same.
#pragma once
#include <cstddef>
#include <span>
#include <vector>

#include "orbit/sgp4.h"

namespace tb::orbit {

// out[j] = sat.propagate_minutes(tsince[j]), to the tolerance above. out.size() >= tsince.size().
void propagate_batch(const Sgp4& sat, std::span<const double> tsince, std::span<Propagation> out);

// The instruction set the kernel runs with here: "avx512f", "avx2" or "baseline".
const char* batch_kernel_isa();
// The kernels this processor can run, best first ("baseline" always), and propagate_batch with one
// of them (for tests and benchmarks). False if `isa` is not one of them.
std::vector<const char*> batch_kernels_available();
bool propagate_batch_with(const char* isa, const Sgp4& sat, std::span<const double> tsince,
                          std::span<Propagation> out);

// A catalogue: every set at every time of a common time grid.
class Sgp4Batch {
 public:
  explicit Sgp4Batch(std::vector<Sgp4> sets) : sets_(std::move(sets)) {}
  const std::vector<Sgp4>& sets() const { return sets_; }

  // out[s * times.size() + j]: set s at times[j]. out.size() >= sets().size() * times.size().
  void propagate(std::span<const UtcTime> times, std::span<Propagation> out) const;

 private:
  std::vector<Sgp4> sets_;
};

}  // namespace tb::orbit
