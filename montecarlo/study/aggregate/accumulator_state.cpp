#include "montecarlo/study/aggregate/accumulator_state.h"

#include <cstdint>
#include <stdexcept>

namespace insmc::mc {
namespace {
constexpr std::string_view kMagic = "insmc-acc3";  // 3: histograms by their filled bins
}  // namespace

std::string serialize_state(const std::vector<OutputStats>& outputs, const KeptSamples& kept) {
  std::string out(kMagic);
  const std::uint64_t n = outputs.size();
  for (int b = 0; b < 8; ++b) out.push_back(static_cast<char>((n >> (8 * b)) & 0xff));
  for (const auto& s : outputs) s.append_to(out);
  kept.append_to(out);
  return out;
}

AccumulatorState deserialize_state(std::string_view bytes) {
  if (bytes.substr(0, kMagic.size()) != kMagic)
    throw std::runtime_error("not an insmc accumulator state (of this version)");
  std::size_t pos = kMagic.size();
  if (bytes.size() < pos + 8) throw std::runtime_error("accumulator state truncated");
  std::uint64_t n = 0;
  for (int b = 0; b < 8; ++b) n |= static_cast<std::uint64_t>(static_cast<unsigned char>(bytes[pos++])) << (8 * b);
  AccumulatorState state;
  // Each output reads its own bytes: a count beyond what the bytes hold
  // ends at the first read past them.
  for (std::uint64_t o = 0; o < n; ++o) state.outputs.push_back(OutputStats::read_from(bytes, pos));
  state.kept = KeptSamples::read_from(bytes, pos);
  if (pos != bytes.size()) throw std::runtime_error("accumulator state has trailing bytes");
  return state;
}

}  // namespace insmc::mc
