// parseMqttUrl: the broker's address and the topic levels as vemd and the clients take them.
#include "util/mqtt_url.h"

#include <gtest/gtest.h>

namespace {

using vem::util::parseMqttUrl;
using vem::util::topicLevelProblem;

TEST(MqttUrl, HostAloneGetsTheDefaultPortAndNoTopicLevels) {
  auto url = parseMqttUrl("mqtt://broker.local");
  ASSERT_TRUE(url) << url.error();
  EXPECT_FALSE(url->tls);
  EXPECT_EQ(url->host, "broker.local");
  EXPECT_EQ(url->port, 1883);
  EXPECT_EQ(url->prefix, "");
  EXPECT_EQ(url->camera, "");
  EXPECT_EQ(url->broker(), "mqtt://broker.local:1883");
}

TEST(MqttUrl, TlsSchemeDefaultsToPort8883) {
  auto url = parseMqttUrl("mqtts://10.0.0.2/vemcast/stage-left");
  ASSERT_TRUE(url) << url.error();
  EXPECT_TRUE(url->tls);
  EXPECT_EQ(url->port, 8883);
  EXPECT_EQ(url->prefix, "vemcast");
  EXPECT_EQ(url->camera, "stage-left");
}

TEST(MqttUrl, UserPortAndBracketedIpv6AreTakenApart) {
  auto url = parseMqttUrl("mqtt://viewer@[::1]:18830/vemcast/cam1/");
  ASSERT_TRUE(url) << url.error();
  EXPECT_EQ(url->username, "viewer");
  EXPECT_EQ(url->host, "::1");
  EXPECT_EQ(url->port, 18830);
  EXPECT_EQ(url->camera, "cam1");
  EXPECT_EQ(url->broker(), "mqtt://[::1]:18830");
}

TEST(MqttUrl, APasswordInTheAddressIsRefusedSoItNeverReachesALog) {
  auto url = parseMqttUrl("mqtt://viewer:secret@host/vemcast/cam1");
  ASSERT_FALSE(url);
  EXPECT_NE(url.error().find("a password does not belong in the address"), std::string::npos);
}

TEST(MqttUrl, WildcardsAndExtraLevelsCannotBecomeTopics) {
  for (const char* bad : {"mqtt://h/vemcast/+", "mqtt://h/#", "mqtt://h/vemcast/a/b",
                          "mqtt://h//cam", "mqtt://h/vem cast"}) {
    auto url = parseMqttUrl(bad);
    EXPECT_FALSE(url) << bad;
  }
}

TEST(MqttUrl, OtherSchemesBadPortsAndMissingHostsAreRefusedInOneSentence) {
  for (const char* bad : {"ws://h:1883", "mqtt://", "mqtt://h:0", "mqtt://h:65536", "mqtt://h:",
                          "mqtt://h:12x", "mqtt://[::1", "mqtt://h?x=1"}) {
    auto url = parseMqttUrl(bad);
    ASSERT_FALSE(url) << bad;
    EXPECT_EQ(url.error().find('\n'), std::string::npos);
    EXPECT_TRUE(url.error().starts_with("the MQTT address ")) << url.error();
  }
}

TEST(MqttUrl, TopicLevelsAreOneLevelOfSafeCharacters) {
  EXPECT_EQ(topicLevelProblem("stage-left_2.a"), "");
  EXPECT_NE(topicLevelProblem(""), "");
  EXPECT_NE(topicLevelProblem("a/b"), "");
  EXPECT_NE(topicLevelProblem("a+"), "");
  EXPECT_NE(topicLevelProblem(std::string(65, 'a')), "");
}

}  // namespace
