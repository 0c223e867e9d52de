// The client's MQTT addresses (client/mqtt_url.h) over the shared parser (daemon/util/mqtt_url.h,
// tested in tests/util/mqtt_url_test.cpp): a camera's address needs PREFIX/CAMERA, a broker's
// takes an optional PREFIX ("vemcast" when absent) and no camera; each refusal is one sentence.
#include "client/mqtt_url.h"

#include <gtest/gtest.h>

namespace vem::client {
namespace {

TEST(ClientMqttUrl, ACameraAddressGivesTheCamerasTopicsAndTheBrokerForSentences) {
  const auto url = parseMqttCameraUrl("mqtt://viewer@broker.local:1884/vemcast/cam-1");
  ASSERT_TRUE(url.has_value()) << url.error();
  EXPECT_EQ(url->username, "viewer");
  EXPECT_EQ(cameraTopic(*url, "lights"), "vemcast/cam-1/lights");
  EXPECT_EQ(brokerHostPort(*url), "broker.local:1884");
  const auto ipv6 = parseMqttCameraUrl("mqtts://[::1]/site/cam");
  ASSERT_TRUE(ipv6.has_value()) << ipv6.error();
  EXPECT_EQ(brokerHostPort(*ipv6), "[::1]:8883");
}

TEST(ClientMqttUrl, ACameraAddressWithoutPrefixAndCameraIsRefusedNamingWhatIsMissing) {
  for (const char* bad : {"mqtt://host", "mqtt://host/", "mqtt://host/vemcast"}) {
    const auto url = parseMqttCameraUrl(bad);
    ASSERT_FALSE(url.has_value()) << bad;
    EXPECT_NE(url.error().find("a camera's address ends with /PREFIX/CAMERA"), std::string::npos)
        << url.error();
    EXPECT_EQ(url.error().find('\n'), std::string::npos);
  }
}

TEST(ClientMqttUrl, WildcardsAndExtraLevelsAreRefusedByTheSharedParser) {
  for (const char* bad :
       {"mqtt://host/vemcast/+", "mqtt://host/vemcast/#", "mqtt://host/vemcast/cam/lights",
        "mqtt://host//cam", "mqtt://viewer:pw@host/vemcast/cam", "ws://host/vemcast/cam"}) {
    EXPECT_FALSE(parseMqttCameraUrl(bad).has_value()) << bad;
    EXPECT_FALSE(parseMqttBrokerUrl(bad).has_value()) << bad;
  }
}

TEST(ClientMqttUrl, ABrokerAddressTakesAnOptionalPrefixDefaultingToVemcast) {
  const auto bare = parseMqttBrokerUrl("mqtt://broker");
  ASSERT_TRUE(bare.has_value()) << bare.error();
  EXPECT_EQ(bare->prefix, "vemcast");
  EXPECT_TRUE(bare->camera.empty());
  const auto site = parseMqttBrokerUrl("mqtts://broker:9000/site-a");
  ASSERT_TRUE(site.has_value()) << site.error();
  EXPECT_EQ(site->prefix, "site-a");
  EXPECT_EQ(site->port, 9000);
}

TEST(ClientMqttUrl, ABrokerAddressRefusesACamera) {
  const auto url = parseMqttBrokerUrl("mqtt://broker/vemcast/cam-1");
  ASSERT_FALSE(url.has_value());
  EXPECT_NE(url.error().find("a broker's address names at most a prefix, no camera"),
            std::string::npos)
      << url.error();
}

TEST(ClientMqttUrl, TellsMqttSchemesApart) {
  EXPECT_TRUE(isMqttUrl("mqtt://h/p/c"));
  EXPECT_TRUE(isMqttUrl("mqtts://h/p/c"));
  EXPECT_FALSE(isMqttUrl("ws://h/"));
  EXPECT_FALSE(isMqttUrl("mqttx://h/"));
}

}  // namespace
}  // namespace vem::client
