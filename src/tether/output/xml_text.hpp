#pragma once
/// \file Escaping text for XML attribute values and character data.

#include <string>
#include <string_view>

namespace tether {

/// `text` with &, <, >, " and ' replaced by their XML entities.
std::string xml_escape(std::string_view text);

}  // namespace tether
