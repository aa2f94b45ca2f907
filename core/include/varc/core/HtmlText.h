// SPDX-License-Identifier: Apache-2.0
// Text for self-contained HTML pages: escaping and base64 for data: URLs.
#pragma once

#include <string>
#include <string_view>

namespace varc {

// |text| with &, <, >, " and ' replaced by character references, safe both as element text and
// inside a quoted attribute. Example: htmlEscape("a<b & 'c'") == "a&lt;b &amp; &#39;c&#39;".
std::string htmlEscape(std::string_view text);

// The standard base64 encoding (RFC 4648, '+' and '/', '=' padding) of |bytes|, as data: URLs
// need. Example: base64Encode("Man") == "TWFu", base64Encode("M") == "TQ==".
std::string base64Encode(std::string_view bytes);

}  // namespace varc
