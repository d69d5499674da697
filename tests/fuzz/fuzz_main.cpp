// libFuzzer's entry points for every target in one program: the name it is
// started under (build/fuzz/fuzz_off, fuzz_obj, ... are links to
// subdivlab_fuzz), or SUBDIVLAB_FUZZ_TARGET, picks the target.

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "fuzz_targets.h"

namespace {

using Target = void (*)(const std::uint8_t*, std::size_t);

struct Named_target {
  const char* name;
  Target run;
};

constexpr Named_target kTargets[] = {
    {"off", subdivlab::fuzz::fuzz_off},
    {"obj", subdivlab::fuzz::fuzz_obj},
    {"ply", subdivlab::fuzz::fuzz_ply},
    {"stl", subdivlab::fuzz::fuzz_stl},
    {"build", subdivlab::fuzz::fuzz_build},
    {"schemes", subdivlab::fuzz::fuzz_schemes},
    {"rules", subdivlab::fuzz::fuzz_rules},
    {"writers", subdivlab::fuzz::fuzz_writers},
};

Target selected = nullptr;

}  // namespace

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
  std::string name;
  if (const char* env = std::getenv("SUBDIVLAB_FUZZ_TARGET")) {
    name = env;
  } else if (*argc > 0) {
    name = (*argv)[0];
    name = name.substr(name.find_last_of('/') + 1);
    if (name.rfind("fuzz_", 0) == 0) name = name.substr(5);
  }
  for (const Named_target& t : kTargets)
    if (name == t.name) selected = t.run;
  if (!selected) {
    std::fprintf(stderr,
                 "subdivlab_fuzz: no target '%s'; start it as "
                 "build/fuzz/fuzz_<target> or set SUBDIVLAB_FUZZ_TARGET, "
                 "targets:",
                 name.c_str());
    for (const Named_target& t : kTargets) std::fprintf(stderr, " %s", t.name);
    std::fprintf(stderr, "\n");
    std::exit(2);
  }
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data,
                                      std::size_t size) {
  selected(data, size);
  return 0;
}
