// The distinct calls a program makes, for scripts/call-climbs/climbs.py: a
// build with -finstrument-functions links this file, and every instrumented
// function entry records (the function, the address it was called from)
// once. At exit the pairs are written to $INSMC_CALL_EDGES as
// "<object> <function offset> <object> <call-site offset>" lines, offsets
// from each object's load address (addr2line reads them).
//
// Not part of insmc: the hooks are compiled without instrumentation, and
// the table is fixed-size (a full table drops further pairs and says so).
#include <dlfcn.h>

#include <atomic>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

namespace {

constexpr std::size_t kSlots = std::size_t{1} << 22;
struct Slot {
  std::atomic<std::uintptr_t> fn{0}, site{0};
};
Slot table[kSlots];
std::atomic<std::uint64_t> dropped{0};

__attribute__((no_instrument_function)) std::size_t slot_of(std::uintptr_t fn, std::uintptr_t site) {
  std::uint64_t h = (fn * 0x9E3779B97F4A7C15ull) ^ (site + 0x632BE59BD9B4E019ull + (fn << 6) + (fn >> 2));
  h ^= h >> 29;
  return static_cast<std::size_t>(h & (kSlots - 1));
}

__attribute__((no_instrument_function)) void record(std::uintptr_t fn, std::uintptr_t site) {
  thread_local std::uintptr_t last_fn = 0, last_site = 0;
  if (fn == last_fn && site == last_site) return;
  last_fn = fn;
  last_site = site;
  for (std::size_t i = slot_of(fn, site), probes = 0; probes < 64; i = (i + 1) & (kSlots - 1), ++probes) {
    std::uintptr_t seen = table[i].fn.load(std::memory_order_acquire);
    if (seen == 0) {
      std::uintptr_t empty = 0;
      if (table[i].fn.compare_exchange_strong(empty, fn)) {
        table[i].site.store(site, std::memory_order_release);
        return;
      }
      seen = empty;
    }
    if (seen == fn) {
      std::uintptr_t s = table[i].site.load(std::memory_order_acquire);
      while (s == 0) s = table[i].site.load(std::memory_order_acquire);  // being written by another thread
      if (s == site) return;
    }
  }
  dropped.fetch_add(1);
}

__attribute__((no_instrument_function)) void write_edge(std::FILE* out, std::uintptr_t fn, std::uintptr_t site) {
  Dl_info f{}, s{};
  if (dladdr(reinterpret_cast<void*>(fn), &f) == 0 || dladdr(reinterpret_cast<void*>(site), &s) == 0) return;
  std::fprintf(out, "%s %lx %s %lx\n", f.dli_fname, static_cast<unsigned long>(fn - reinterpret_cast<std::uintptr_t>(f.dli_fbase)),
               s.dli_fname, static_cast<unsigned long>(site - reinterpret_cast<std::uintptr_t>(s.dli_fbase)));
}

__attribute__((no_instrument_function, destructor)) void write_edges() {
  const char* path = std::getenv("INSMC_CALL_EDGES");
  if (path == nullptr) return;
  std::FILE* out = std::fopen(path, "w");
  if (out == nullptr) return;
  for (const Slot& slot : table) {
    const std::uintptr_t fn = slot.fn.load(), site = slot.site.load();
    if (fn != 0 && site != 0) write_edge(out, fn, site);
  }
  if (dropped.load() != 0) std::fprintf(stderr, "call_edges: table full, %llu calls not recorded\n",
                                        static_cast<unsigned long long>(dropped.load()));
  std::fclose(out);
}

}  // namespace

extern "C" {
__attribute__((no_instrument_function)) void __cyg_profile_func_enter(void* fn, void* site) {
  record(reinterpret_cast<std::uintptr_t>(fn), reinterpret_cast<std::uintptr_t>(site));
}
__attribute__((no_instrument_function)) void __cyg_profile_func_exit(void*, void*) {}
}
