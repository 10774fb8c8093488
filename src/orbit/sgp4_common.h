// Arithmetic that the scalar propagator (sgp4.cpp) and the batch kernel (sgp4_batch.cpp) share,
// written once (private to src/orbit). Always inline: the kernel's loops over lanes must stay simple
// loops the compiler vectorises, and the scalar code keeps its results to the bit.
#pragma once

namespace tb::orbit::detail {

struct SinCos {
  double s, c;
};

// The unit position vector u and the unit vector v along the track (the paper's ux, uy, uz and
// vx, vy, vz) from the argument of latitude, the node and the inclination (sines and cosines).
struct Orientation {
  double ux, uy, uz, vx, vy, vz;
};
[[gnu::always_inline]] inline Orientation orientation(SinCos s, SinCos node, SinCos inc) {
  const double xmx = -node.s * inc.c;
  const double xmy = node.c * inc.c;
  const double ux = xmx * s.s + node.c * s.c;
  const double uy = xmy * s.s + node.s * s.c;
  const double uz = inc.s * s.s;
  const double vx = xmx * s.c - node.c * s.s;
  const double vy = xmy * s.c - node.s * s.s;
  const double vz = inc.s * s.c;
  return {ux, uy, uz, vx, vy, vz};
}

}  // namespace tb::orbit::detail
