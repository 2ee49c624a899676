#pragma once
// The text handed to TinyXML (the SRDF reader; urdfdom's URDF parser), padded with NULs. TinyXML
// 2.6 reads a UTF-8 character whole from its lead byte, so a text that ends inside one (a file
// cut after 0xE1) is read up to 5 bytes past its terminator: found by the SRDF fuzzer under
// AddressSanitizer (a heap-buffer-overflow in TiXmlBase's memcpy of the character). Parsing stops
// at the first NUL; the ones after it keep those reads inside the buffer.
#include <string>
#include <string_view>

namespace stanceplan {

inline constexpr std::size_t kXmlPadding = 8;

inline std::string xml_parse_buffer(std::string_view xml) {
  std::string buffer;
  buffer.reserve(xml.size() + kXmlPadding);
  buffer.append(xml);
  buffer.append(kXmlPadding, '\0');
  return buffer;
}

}  // namespace stanceplan
