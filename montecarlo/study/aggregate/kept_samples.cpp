#include "montecarlo/study/aggregate/kept_samples.h"

#include <algorithm>
#include <bit>

#include "lib/common/assert.h"
#include "montecarlo/study/aggregate/byte_io.h"
#include "montecarlo/study/model/study_config.h"

namespace insmc::mc {

KeptSamples::KeptSamples(std::uint64_t outputs, std::uint64_t samples) : outputs_(outputs), samples_(samples) {
  if (outputs_ == 0) return;
  const std::uint64_t blocks = (samples + kBlockSize - 1) / kBlockSize;
  // The value budget shared by the kept outputs, in whole blocks (at least one).
  kept_blocks_ = std::min(blocks, std::max<std::uint64_t>(1, kMaxKeptValues / (outputs_ * kBlockSize)));
  filled_.assign(kept_blocks_, 0);
  values_.assign(kept_blocks_ * outputs_ * kBlockSize, 0.0f);
}

float* KeptSamples::slot(std::uint64_t block, std::uint64_t output) {
  INSMC_ASSERT(block < kept_blocks_ && output < outputs_, "kept slot ({}, {}) of ({}, {})", block, output,
               kept_blocks_, outputs_);
  return values_.data() + (block * outputs_ + output) * kBlockSize;
}

std::uint64_t KeptSamples::block_values(std::uint64_t block) const {
  // Every block is full but the study's last.
  return std::min(kBlockSize, samples_ - block * kBlockSize);
}

void KeptSamples::merge(const KeptSamples& o) {
  if (o.outputs_ == 0) return;
  if (outputs_ == 0) {
    *this = o;
    return;
  }
  INSMC_ASSERT(o.outputs_ == outputs_ && o.samples_ == samples_, "merging kept samples of different studies");
  const std::uint64_t stride = outputs_ * kBlockSize;
  for (std::uint64_t b = 0; b < kept_blocks_; ++b) {
    if (!o.filled_[b]) continue;
    INSMC_ASSERT(!filled_[b], "kept block {} merged twice", b);
    std::copy_n(o.values_.begin() + static_cast<std::ptrdiff_t>(b * stride), stride,
                values_.begin() + static_cast<std::ptrdiff_t>(b * stride));
    filled_[b] = 1;
  }
}

std::vector<float> KeptSamples::values(std::uint64_t output) const {
  std::vector<float> out;
  for (std::uint64_t b = 0; b < kept_blocks_; ++b) {
    if (!filled_[b]) continue;
    const auto first = values_.begin() + static_cast<std::ptrdiff_t>((b * outputs_ + output) * kBlockSize);
    out.insert(out.end(), first, first + static_cast<std::ptrdiff_t>(block_values(b)));
  }
  return out;
}

void KeptSamples::append_to(std::string& out) const {
  using byte_io::put_u32, byte_io::put_u64, byte_io::put_u8;
  put_u64(out, outputs_);
  put_u64(out, samples_);
  put_u64(out, kept_blocks_);
  for (std::uint8_t f : filled_) put_u8(out, f);
  for (float v : values_) put_u32(out, std::bit_cast<std::uint32_t>(v));
}

KeptSamples KeptSamples::read_from(std::string_view bytes, std::size_t& pos) {
  byte_io::Reader in(bytes, "KeptSamples", pos);
  const std::uint64_t outputs = in.u64(), samples = in.u64(), kept_blocks = in.u64();
  KeptSamples k;
  if (outputs == 0 && (samples != 0 || kept_blocks != 0)) in.fail("kept blocks without kept outputs");
  if (outputs != 0) {
    // Sizes checked against the bytes present before anything is allocated
    // (a state that keeps anything keeps at least one block).
    if (kept_blocks == 0 || outputs > kMaxKeptValues || kept_blocks > kMaxKeptValues / outputs ||
        in.remaining() < kept_blocks * (1 + 4 * outputs * kBlockSize))
      in.fail("kept samples larger than the state");
    k = KeptSamples(outputs, samples);
    if (k.kept_blocks_ != kept_blocks) in.fail("kept blocks do not match the sample count");
  }
  for (auto& f : k.filled_) {
    f = in.u8();
    if (f > 1) in.fail("a filled flag other than 0 or 1");
  }
  for (float& v : k.values_) v = std::bit_cast<float>(in.u32());
  pos = in.position();
  return k;
}

}  // namespace insmc::mc
