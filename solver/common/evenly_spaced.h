#pragma once
// The i-th of `count` equally spaced values from `start` to `stop` (START:STOP:COUNT ranges of the
// command line, sweep axes): exact at both ends, interpolated from both ends so that rounding is
// symmetric. One formula everywhere, so that a sweep's stored axis and its points agree bit for
// bit.
namespace flexure {

inline double evenly_spaced(double start, double stop, long count, long i) {
  if (count <= 1) return start;
  if (i == count - 1) return stop;
  const double f = static_cast<double>(i) / static_cast<double>(count - 1);
  return start * (1.0 - f) + stop * f;
}

}  // namespace flexure
