#include "tether/output/base64_encoder.hpp"

namespace tether {

namespace {

constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

void encode_triple(const unsigned char* b, char* out) {
  const unsigned v = (unsigned{b[0]} << 16) | (unsigned{b[1]} << 8) | unsigned{b[2]};
  out[0] = kAlphabet[(v >> 18) & 63];
  out[1] = kAlphabet[(v >> 12) & 63];
  out[2] = kAlphabet[(v >> 6) & 63];
  out[3] = kAlphabet[v & 63];
}

}  // namespace

void Base64Encoder::add(const void* bytes, std::size_t n) {
  const auto* in = static_cast<const unsigned char*>(bytes);
  // Complete a held-back triple first.
  while (n_pending_ > 0 && n > 0) {
    pending_[n_pending_++] = *in++;
    --n;
    if (n_pending_ == 3) {
      char quad[4];
      encode_triple(pending_.data(), quad);
      out_.append(quad, 4);
      n_pending_ = 0;
    }
  }
  const std::size_t n_triples = n / 3;
  const std::size_t old_size = out_.size();
  out_.resize(old_size + 4 * n_triples);
  char* dst = out_.data() + old_size;
  for (std::size_t t = 0; t < n_triples; ++t, in += 3, dst += 4) encode_triple(in, dst);
  n -= 3 * n_triples;
  for (std::size_t i = 0; i < n; ++i) pending_[n_pending_++] = in[i];
}

void Base64Encoder::finish() {
  if (n_pending_ == 0) return;
  const unsigned char b[3] = {pending_[0], n_pending_ > 1 ? pending_[1] : static_cast<unsigned char>(0), 0};
  char quad[4];
  encode_triple(b, quad);
  if (n_pending_ == 1) quad[2] = '=';
  quad[3] = '=';
  out_.append(quad, 4);
  n_pending_ = 0;
}

std::string base64_encode(const void* bytes, std::size_t n) {
  std::string out;
  out.reserve((n + 2) / 3 * 4);
  Base64Encoder encoder(out);
  encoder.add(bytes, n);
  encoder.finish();
  return out;
}

}  // namespace tether
