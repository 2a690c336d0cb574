#pragma once
/// \file The restart file (`JOB.rst`): a RestartState in a small binary format.
///
/// Layout (all integers little-endian, doubles as their IEEE-754 bits, so a
/// state read back is bitwise the state written):
///
///   magic     8 bytes  "TETHRST\0"
///   version   u32      kRestartFormatVersion
///   order     u32      0x01020304 (byte-order check)
///   length    u64      bytes of the payload
///   payload            the fields of RestartState in declaration order:
///                      strings as u64 length + bytes, integers as i64,
///                      doubles as u64 bits, vectors as u64 count + items
///   checksum  u64      FNV-1a 64 of every byte before it
///
/// A file is accepted only when the magic, version, byte order, length and
/// checksum agree and the payload is consumed exactly; anything else
/// (truncated, corrupt, another format) is refused with an InputError naming
/// the file, never read half-way.

#include <filesystem>
#include <string>
#include <string_view>

#include "tether/model/restart_state.hpp"

namespace tether {

/// 2: dynamic motion state; 3: the static predictor; 4: *PLASTIC points carry
/// the yield flag (AC YIELD), 14 state values instead of 13.
inline constexpr std::uint32_t kRestartFormatVersion = 4;

/// The bytes of the file for `state`.
std::string encode_restart(const RestartState& state);

/// Decodes the bytes of a restart file; `file` names it in errors (InputError).
RestartState decode_restart(std::string_view bytes, const std::string& file);

/// Writes `path` atomically (`path.tmp`, then rename: a reader, or a later
/// restart after a crash, sees the previous complete state or the new one).
/// Throws std::runtime_error naming the file on I/O errors.
void write_restart_file(const std::filesystem::path& path, const RestartState& state);

/// Reads and decodes `path`; InputError naming it when it cannot be read or is
/// not a complete restart file.
RestartState read_restart_file(const std::filesystem::path& path);

}  // namespace tether
