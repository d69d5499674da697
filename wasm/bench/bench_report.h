// What the native benchmarks print: one JSON object per scheme on stdout
// (scheme, faces, median_ms, runs_ms), read by scripts/bench.mjs.
#ifndef SUBDIVLAB_BENCH_REPORT_H
#define SUBDIVLAB_BENCH_REPORT_H

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

namespace subdivlab_bench {

inline double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

/** Prints one scheme's result line and flushes it (the caller reads line by
 * line). */
inline void print_result(const std::string& scheme, std::size_t faces,
                         const std::vector<double>& times_ms) {
  std::printf(
      "{\"scheme\":\"%s\",\"faces\":%zu,\"median_ms\":%.3f,\"runs_ms\":[",
      scheme.c_str(), faces, median(times_ms));
  for (std::size_t i = 0; i < times_ms.size(); ++i)
    std::printf("%s%.3f", i ? "," : "", times_ms[i]);
  std::printf("]}\n");
  std::fflush(stdout);
}

}  // namespace subdivlab_bench

#endif  // SUBDIVLAB_BENCH_REPORT_H
