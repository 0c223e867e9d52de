// The stream address parser accepts ws[s]://host[:port][/path] and refuses everything else with a
// sentence (client/stream_url.h).
#include "client/stream_url.h"

#include <gtest/gtest.h>

namespace vem::client {
namespace {

TEST(StreamUrl, ParsesHostPortAndPath) {
  const auto url = parseStreamUrl("ws://render-box.local:8490/stream?token=abc");
  ASSERT_TRUE(url.has_value()) << url.error();
  EXPECT_FALSE(url->tls);
  EXPECT_EQ(url->host, "render-box.local");
  EXPECT_EQ(url->port, 8490);
  EXPECT_EQ(url->target, "/stream?token=abc");
  EXPECT_EQ(url->hostHeader(), "render-box.local:8490");
}

TEST(StreamUrl, DefaultsThePortAndPathOfEachScheme) {
  const auto ws = parseStreamUrl("ws://10.0.0.2");
  ASSERT_TRUE(ws.has_value());
  EXPECT_EQ(ws->port, 80);
  EXPECT_EQ(ws->target, "/");
  const auto wss = parseStreamUrl("wss://example.org?x=1");
  ASSERT_TRUE(wss.has_value());
  EXPECT_TRUE(wss->tls);
  EXPECT_EQ(wss->port, 443);
  EXPECT_EQ(wss->target, "/?x=1");
}

TEST(StreamUrl, StripsTheBracketsOfAnIpv6Host) {
  const auto url = parseStreamUrl("ws://[::1]:9000/");
  ASSERT_TRUE(url.has_value()) << url.error();
  EXPECT_EQ(url->host, "::1");
  EXPECT_EQ(url->port, 9000);
  EXPECT_EQ(url->hostHeader(), "[::1]:9000");
}

TEST(StreamUrl, RefusesWhatIsNotAStreamAddress) {
  for (const char* bad :
       {"http://host:80/", "host:8490", "ws://", "ws://:8490/", "ws://host:/", "ws://host:0/",
        "ws://host:65536/", "ws://host:12x/", "ws://user@host/", "ws://host/#frag",
        "ws://[::1/", "ws://[::1]x/", "ws://ho st/", "ws://host:80:81/"}) {
    const auto url = parseStreamUrl(bad);
    ASSERT_FALSE(url.has_value()) << bad;
    EXPECT_NE(url.error().find("is not a stream address"), std::string::npos) << url.error();
  }
}

}  // namespace
}  // namespace vem::client
