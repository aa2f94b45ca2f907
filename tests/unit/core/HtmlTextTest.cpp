// SPDX-License-Identifier: Apache-2.0
// htmlEscape and base64Encode: the RFC 4648 test vectors and every character HTML reserves.
#include "varc/core/HtmlText.h"

#include <gtest/gtest.h>

#include <string>

namespace varc {
namespace {

TEST(HtmlTextTest, EscapesEveryReservedCharacter) {
    EXPECT_EQ(htmlEscape("a<b & 'c' > \"d\""), "a&lt;b &amp; &#39;c&#39; &gt; &quot;d&quot;");
    EXPECT_EQ(htmlEscape("shader 'Custom/Lit' {DIRECTIONAL}"),
              "shader &#39;Custom/Lit&#39; {DIRECTIONAL}");
    EXPECT_EQ(htmlEscape(""), "");
}

TEST(HtmlTextTest, Base64MatchesRfc4648Vectors) {
    EXPECT_EQ(base64Encode(""), "");
    EXPECT_EQ(base64Encode("f"), "Zg==");
    EXPECT_EQ(base64Encode("fo"), "Zm8=");
    EXPECT_EQ(base64Encode("foo"), "Zm9v");
    EXPECT_EQ(base64Encode("foob"), "Zm9vYg==");
    EXPECT_EQ(base64Encode("fooba"), "Zm9vYmE=");
    EXPECT_EQ(base64Encode("foobar"), "Zm9vYmFy");
}

TEST(HtmlTextTest, Base64EncodesHighBytes) {
    EXPECT_EQ(base64Encode(std::string("\xff\xfe\x00", 3)), "//4A");
    EXPECT_EQ(base64Encode(std::string("\x89PNG", 4)), "iVBORw==");
}

}  // namespace
}  // namespace varc
