// ocean-bench: benchmark programs that print JSON, one subcommand per bench_*.cpp.
#include "bench.hpp"

#include <cstdio>
#include <cstring>
#include <map>
#include <string>

namespace ocean::bench {
namespace {
struct Entry {
  const char* summary;
  BenchFn fn;
};
std::map<std::string, Entry>& registry() {
  static std::map<std::string, Entry> r;
  return r;
}
}  // namespace

Registrar::Registrar(const char* name, const char* summary, BenchFn fn) { registry()[name] = {summary, fn}; }

}  // namespace ocean::bench

int main(int argc, char** argv) {
  using namespace ocean::bench;
  auto& r = registry();
  if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h")) {
    std::printf("usage: ocean-bench <bench> [options]   (ocean-bench <bench> --help for its options)\n\nbenches:\n");
    for (auto& [name, e] : r) std::printf("  %-10s %s\n", name.c_str(), e.summary);
    return argc < 2 ? 2 : 0;
  }
  auto it = r.find(argv[1]);
  if (it == r.end()) {
    std::fprintf(stderr, "ocean-bench: unknown bench '%s' (try --help)\n", argv[1]);
    return 2;
  }
  return it->second.fn(argc - 1, argv + 1);
}
