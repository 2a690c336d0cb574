#include "tether/output/restart_file.hpp"

#include <bit>
#include <cstring>
#include <fstream>
#include <sstream>

#include "tether/core/error.hpp"
#include "tether/output/atomic_file.hpp"

namespace tether {

namespace {

constexpr std::string_view kMagic{"TETHRST\0", 8};
constexpr std::uint32_t kByteOrder = 0x01020304;
constexpr std::size_t kHeader = 8 + 4 + 4 + 8;  // magic, version, order, length
constexpr std::size_t kTrailer = 8;             // checksum

std::uint64_t fnv1a(std::string_view bytes) {
  std::uint64_t h = 14695981039346656037ull;
  for (unsigned char c : bytes) h = (h ^ c) * 1099511628211ull;
  return h;
}

class Encoder {
 public:
  void u32(std::uint32_t v) {
    for (int k = 0; k < 4; ++k) out_.push_back(static_cast<char>((v >> (8 * k)) & 0xff));
  }
  void u64(std::uint64_t v) {
    for (int k = 0; k < 8; ++k) out_.push_back(static_cast<char>((v >> (8 * k)) & 0xff));
  }
  void i64(std::int64_t v) { u64(static_cast<std::uint64_t>(v)); }
  void f64(double v) { u64(std::bit_cast<std::uint64_t>(v)); }
  void text(std::string_view s) {
    u64(s.size());
    out_.append(s);
  }
  void doubles(const std::vector<double>& v) {
    u64(v.size());
    for (double x : v) f64(x);
  }
  void raw(std::string_view s) { out_.append(s); }
  [[nodiscard]] std::string& bytes() { return out_; }

 private:
  std::string out_;
};

class Decoder {
 public:
  Decoder(std::string_view bytes, const std::string& file) : in_(bytes), file_(file) {}

  [[noreturn]] void fail(const std::string& why) const {
    throw InputError(SourceLocation{file_, 0}, "not a usable tether restart file: " + why);
  }
  std::string_view take(std::size_t n, const char* what) {
    if (n > in_.size() - pos_)
      fail("truncated: " + std::string(what) + " at byte " + std::to_string(pos_) + " needs " + std::to_string(n) +
           " bytes, " + std::to_string(in_.size() - pos_) + " remain");
    const std::string_view s = in_.substr(pos_, n);
    pos_ += n;
    return s;
  }
  std::uint32_t u32(const char* what) {
    const std::string_view s = take(4, what);
    std::uint32_t v = 0;
    for (int k = 3; k >= 0; --k) v = (v << 8) | static_cast<unsigned char>(s[static_cast<std::size_t>(k)]);
    return v;
  }
  std::uint64_t u64(const char* what) {
    const std::string_view s = take(8, what);
    std::uint64_t v = 0;
    for (int k = 7; k >= 0; --k) v = (v << 8) | static_cast<unsigned char>(s[static_cast<std::size_t>(k)]);
    return v;
  }
  std::int64_t i64(const char* what) { return static_cast<std::int64_t>(u64(what)); }
  int int32(const char* what) {
    const std::int64_t v = i64(what);
    if (v < INT32_MIN || v > INT32_MAX) fail(std::string(what) + " out of range (" + std::to_string(v) + ")");
    return static_cast<int>(v);
  }
  double f64(const char* what) { return std::bit_cast<double>(u64(what)); }
  /// A count of items of `item_bytes` each that must fit in what remains.
  std::size_t count(const char* what, std::size_t item_bytes) {
    const std::uint64_t n = u64(what);
    if (n > (in_.size() - pos_) / item_bytes)
      fail(std::string(what) + ": " + std::to_string(n) + " items do not fit in the " +
           std::to_string(in_.size() - pos_) + " bytes left");
    return static_cast<std::size_t>(n);
  }
  std::string text(const char* what) { return std::string(take(count(what, 1), what)); }
  std::vector<double> doubles(const char* what) {
    std::vector<double> v(count(what, 8));
    for (double& x : v) x = f64(what);
    return v;
  }
  [[nodiscard]] std::size_t remaining() const { return in_.size() - pos_; }
  [[nodiscard]] std::size_t position() const { return pos_; }

 private:
  std::string_view in_;
  std::size_t pos_ = 0;
  const std::string& file_;
};

void encode_payload(Encoder& e, const RestartState& s) {
  e.text(s.written_by);
  e.text(s.deck);
  const RestartFingerprint& f = s.fingerprint;
  e.i64(f.nodes), e.i64(f.elements), e.i64(f.dofs), e.i64(f.multipliers), e.i64(f.contributions);
  e.u64(f.nodes_hash), e.u64(f.elements_hash), e.u64(f.history_hash), e.i64(f.history_steps);
  e.i64(s.step), e.i64(s.increment), e.i64(s.step_completed ? 1 : 0);
  e.f64(s.step_time), e.f64(s.step_start_time), e.f64(s.total_time);
  e.f64(s.dt), e.i64(s.easy_in_row), e.f64(s.averaged_force), e.i64(s.n_averaged);
  e.doubles(s.predictor_increment), e.f64(s.predictor_dt);
  e.i64(s.steps_completed), e.i64(s.increments), e.i64(s.iterations), e.i64(s.cutbacks);
  e.doubles(s.u);
  e.doubles(s.u_step_start);
  for (const auto* loads : {&s.cload_end, &s.pressure_end}) {
    e.u64(loads->size());
    for (const CarriedLoad& l : *loads) e.i64(l.first), e.i64(l.second), e.f64(l.value);
  }
  e.u64(s.contributions.size());
  for (const ContributionState& c : s.contributions) e.i64(c.index), e.doubles(c.values);
  e.doubles(s.output_state);
  e.doubles(s.motion);
}

RestartState decode_payload(Decoder& d) {
  RestartState s;
  s.written_by = d.text("writer");
  s.deck = d.text("deck name");
  RestartFingerprint& f = s.fingerprint;
  f.nodes = d.i64("node count"), f.elements = d.i64("element count"), f.dofs = d.i64("dof count");
  f.multipliers = d.i64("multiplier count"), f.contributions = d.i64("contribution count");
  f.nodes_hash = d.u64("node hash"), f.elements_hash = d.u64("element hash");
  f.history_hash = d.u64("history hash"), f.history_steps = d.i64("history steps");
  s.step = d.int32("step"), s.increment = d.int32("increment");
  const std::int64_t completed = d.i64("step-completed flag");
  if (completed != 0 && completed != 1) d.fail("bad step-completed flag " + std::to_string(completed));
  s.step_completed = completed == 1;
  s.step_time = d.f64("step time"), s.step_start_time = d.f64("step start time"), s.total_time = d.f64("total time");
  s.dt = d.f64("increment size"), s.easy_in_row = d.int32("easy increments");
  s.averaged_force = d.f64("averaged force"), s.n_averaged = d.int32("averaged increments");
  s.predictor_increment = d.doubles("predictor increment"), s.predictor_dt = d.f64("predictor increment size");
  s.steps_completed = d.int32("steps completed"), s.increments = d.int32("increments");
  s.iterations = d.int32("iterations"), s.cutbacks = d.int32("cut-backs");
  s.u = d.doubles("unknowns");
  s.u_step_start = d.doubles("unknowns at the step start");
  for (auto* loads : {&s.cload_end, &s.pressure_end}) {
    loads->resize(d.count("carried loads", 24));
    for (CarriedLoad& l : *loads)
      l.first = d.i64("carried load"), l.second = d.i64("carried load"), l.value = d.f64("carried load");
  }
  s.contributions.resize(d.count("contribution states", 16));
  for (ContributionState& c : s.contributions)
    c.index = d.i64("contribution index"), c.values = d.doubles("contribution state");
  s.output_state = d.doubles("output state");
  s.motion = d.doubles("dynamic state");
  return s;
}

}  // namespace

std::string encode_restart(const RestartState& state) {
  Encoder payload;
  encode_payload(payload, state);
  Encoder e;
  e.raw(kMagic);
  e.u32(kRestartFormatVersion);
  e.u32(kByteOrder);
  e.u64(payload.bytes().size());
  e.raw(payload.bytes());
  e.u64(fnv1a(e.bytes()));
  return std::move(e.bytes());
}

RestartState decode_restart(std::string_view bytes, const std::string& file) {
  Decoder d(bytes, file);
  if (bytes.size() < kMagic.size() || bytes.substr(0, kMagic.size()) != kMagic)
    d.fail(bytes.empty() ? "the file is empty" : "it does not start with the restart-file magic \"TETHRST\"");
  d.take(kMagic.size(), "magic");
  const std::uint32_t version = d.u32("version");
  if (version != kRestartFormatVersion)
    d.fail("format version " + std::to_string(version) + ", this tether reads version " +
           std::to_string(kRestartFormatVersion));
  if (d.u32("byte order") != kByteOrder) d.fail("bad byte-order mark");
  const std::uint64_t length = d.u64("payload length");
  if (bytes.size() < kHeader + kTrailer || length != bytes.size() - kHeader - kTrailer)
    d.fail("truncated or extended: the header announces " + std::to_string(length) + " bytes of state, the file has " +
           std::to_string(bytes.size() < kHeader + kTrailer ? 0 : bytes.size() - kHeader - kTrailer) +
           " (an interrupted copy?)");
  Decoder trailer(bytes.substr(bytes.size() - kTrailer), file);
  if (trailer.u64("checksum") != fnv1a(bytes.substr(0, bytes.size() - kTrailer)))
    d.fail("checksum mismatch: the file is corrupt");
  Decoder payload(bytes.substr(kHeader, static_cast<std::size_t>(length)), file);
  RestartState s = decode_payload(payload);
  if (payload.remaining() != 0)
    payload.fail(std::to_string(payload.remaining()) + " unexpected bytes after the state");
  return s;
}

void write_restart_file(const std::filesystem::path& path, const RestartState& state) {
  const std::string bytes = encode_restart(state);
  AtomicFile file(path);
  file.stream().write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  file.commit();
}

RestartState read_restart_file(const std::filesystem::path& path) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error))
    throw InputError(SourceLocation{path.string(), 0},
                     std::filesystem::exists(path, error) ? "not a regular file: expected a restart file (.rst)"
                                                          : "cannot open the restart file: it does not exist");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(SourceLocation{path.string(), 0}, "cannot open the restart file");
  std::ostringstream bytes;
  bytes << in.rdbuf();
  if (in.bad()) throw InputError(SourceLocation{path.string(), 0}, "read error");
  return decode_restart(bytes.view(), path.string());
}

}  // namespace tether
