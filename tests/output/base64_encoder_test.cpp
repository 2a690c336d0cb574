#include "tether/output/base64_encoder.hpp"

#include <gtest/gtest.h>

#include <string>

namespace tether {
namespace {

TEST(Base64Encoder, Rfc4648TestVectors) {
  const std::pair<std::string, std::string> vectors[] = {
      {"", ""},         {"f", "Zg=="},         {"fo", "Zm8="},         {"foo", "Zm9v"},
      {"foob", "Zm9vYg=="}, {"fooba", "Zm9vYmE="}, {"foobar", "Zm9vYmFy"}};
  for (const auto& [plain, encoded] : vectors) EXPECT_EQ(base64_encode(plain.data(), plain.size()), encoded) << plain;
}

TEST(Base64Encoder, PiecewiseInputEqualsOneShot) {
  std::string bytes;
  for (int i = 0; i < 1000; ++i) bytes += static_cast<char>((i * 37 + 11) & 0xff);
  const std::string whole = base64_encode(bytes.data(), bytes.size());
  for (const std::size_t piece : {1u, 2u, 4u, 7u, 8u, 64u}) {
    std::string out;
    Base64Encoder encoder(out);
    std::string flushed;
    for (std::size_t pos = 0; pos < bytes.size(); pos += piece) {
      encoder.add(bytes.data() + pos, std::min(piece, bytes.size() - pos));
      flushed += out;  // the caller may empty the buffer between calls
      out.clear();
    }
    encoder.finish();
    EXPECT_EQ(flushed + out, whole) << "piece " << piece;
  }
}

}  // namespace
}  // namespace tether
