// Native side of `npm run bench`: times one subdivision step of each scheme on
// a mesh with CGAL's own hosts (Subdivide_options::cgal_hosts; the fast hosts
// are the WASM side's), natively, and prints one
// JSON object per scheme (scheme, faces, median_ms, runs_ms) on stdout.
// A scheme `custom:NAME` runs the custom scheme with the rules of preset NAME
// (custom_rules_preset, the weights of public/rules/NAME.json) on CGAL's host.
// Usage: subdiv_bench_native MESH.off RUNS LEVELS [SCHEME...]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "bench_report.h"
#include "core/custom_rules.h"
#include "core/mesh_io.h"
#include "core/subdivide.h"

int main(int argc, char** argv) {
  using namespace subdivlab;
  if (argc < 4) {
    std::cerr
        << "usage: subdiv_bench_native MESH.off RUNS LEVELS [SCHEME...]\n";
    return 2;
  }
  const std::string path = argv[1];
  const int runs = std::max(1, std::atoi(argv[2]));
  const int levels = std::max(1, std::atoi(argv[3]));
  std::vector<std::string> schemes;
  for (int i = 4; i < argc; ++i) schemes.push_back(argv[i]);
  if (schemes.empty())
    schemes = {"catmull-clark", "loop", "doo-sabin", "sqrt3"};

  std::ifstream file(path, std::ios::binary);
  if (!file) {
    std::cerr << "error: " << path << ": cannot read\n";
    return 1;
  }
  std::stringstream text;
  text << file.rdbuf();
  const std::string name = path.substr(path.find_last_of('/') + 1);
  const Mesh_format format =
      name.size() > 4 && name.substr(name.size() - 4) == ".obj"
          ? Mesh_format::obj
          : Mesh_format::off;
  const Result<Mesh_buffers> mesh = read_mesh(text.str(), format);
  if (!mesh.ok()) {
    std::cerr << "error: " << path << ": " << mesh.status.message << "\n";
    return 1;
  }

  for (const std::string& scheme : schemes) {
    Subdivide_options options;
    options.scheme = scheme;
    const std::string custom = "custom:";
    if (scheme.compare(0, custom.size(), custom) == 0) {
      options.scheme = "custom";
      options.custom = custom_rules_preset(scheme.substr(custom.size()));
    }
    options.levels = levels;
    options.cgal_hosts = true;  // the reference: CGAL's own hosts
    std::vector<double> times;
    std::size_t faces = 0;
    // One untimed warm-up run, then `runs` timed ones.
    for (int r = 0; r <= runs; ++r) {
      const auto start = std::chrono::steady_clock::now();
      const Result<Mesh_buffers> out = subdivide_mesh(mesh.value, options);
      const auto stop = std::chrono::steady_clock::now();
      if (!out.ok()) {
        std::cerr << "error: " << scheme << ": " << out.status.message << "\n";
        return 1;
      }
      faces = out.value.face_count();
      if (r > 0)
        times.push_back(
            std::chrono::duration<double, std::milli>(stop - start).count());
    }
    subdivlab_bench::print_result(scheme, faces, times);
  }
  return 0;
}
