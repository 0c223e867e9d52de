// util/log_setup.h: the JSON format gives one valid JSON object per message whatever the message
// holds (quotes, newlines, control bytes, invalid UTF-8), the journald format carries the syslog
// priority and no time of its own, and the level names read back.
#include "util/log_setup.h"

#include <memory>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <spdlog/logger.h>
#include <spdlog/sinks/ostream_sink.h>
#include <nlohmann/json.hpp>

namespace vem::cli {
namespace {

// What a logger named "vemd" with `options` writes for the messages.
std::string logged(const LogOptions& options, spdlog::level::level_enum level,
                   const std::string& message) {
  std::ostringstream out;
  auto sink = std::make_shared<spdlog::sinks::ostream_sink_mt>(out);
  spdlog::logger logger("vemd", sink);
  logger.set_formatter(makeLogFormatter(options));
  logger.set_level(spdlog::level::trace);
  logger.log(level, "{}", message);
  logger.flush();
  return out.str();
}

// Catches a JSON log line built by string concatenation: a message with quotes, a newline, a
// backslash, a control byte and invalid UTF-8 (a camera's text) must stay one valid JSON line.
TEST(LogSetup, JsonMessageWithQuotesAndNewlineIsOneValidJsonLine) {
  const std::string message = "camera \"left\" said:\nno \\ signal\x01 \xff";
  const std::string line =
      logged({spdlog::level::info, LogFormat::Json, false}, spdlog::level::warn, message);
  ASSERT_FALSE(line.empty());
  EXPECT_EQ(line.back(), '\n');
  EXPECT_EQ(line.find('\n'), line.size() - 1) << line;
  const nlohmann::json parsed = nlohmann::json::parse(line);
  EXPECT_EQ(parsed.at("level"), "warning");
  EXPECT_EQ(parsed.at("logger"), "vemd");
  EXPECT_EQ(parsed.at("message").get<std::string>().substr(0, 25), "camera \"left\" said:\nno \\ ");
  const std::string time = parsed.at("time");
  ASSERT_EQ(time.size(), 24u) << time;  // 2026-12-03T14:57:37.141Z
  EXPECT_EQ(time[10], 'T');
  EXPECT_EQ(time.back(), 'Z');
  EXPECT_EQ(line.rfind("{\"time\":", 0), 0u) << "time, level, logger, message in order: " << line;
}

TEST(LogSetup, JournalLinesCarryTheSyslogPriorityAndNoTime) {
  const LogOptions journal{spdlog::level::info, LogFormat::Text, true};
  EXPECT_EQ(logged(journal, spdlog::level::warn, "slow"), "<4>warning: slow\n");
  EXPECT_EQ(logged(journal, spdlog::level::err, "gone"), "<3>error: gone\n");
  EXPECT_EQ(logged(journal, spdlog::level::info, "ok"), "<6>info: ok\n");
  EXPECT_EQ(logged(journal, spdlog::level::debug, "d"), "<7>debug: d\n");
}

TEST(LogSetup, TextLinesStartWithTheTimeAndNameTheLogger) {
  const std::string line =
      logged({spdlog::level::info, LogFormat::Text, false}, spdlog::level::info, "hello");
  EXPECT_EQ(line.size(), std::string("2026-12-03 14:57:37.141 vemd info: hello\n").size()) << line;
  EXPECT_NE(line.find(" vemd info: hello\n"), std::string::npos) << line;
}

TEST(LogSetup, LevelAndFormatNamesReadBack) {
  for (const char* name : {"trace", "debug", "info", "warn", "error", "off"}) {
    const auto level = parseLogLevel(name);
    ASSERT_TRUE(level) << name;
    EXPECT_EQ(logLevelName(*level), name);
  }
  EXPECT_FALSE(parseLogLevel("warning"));
  EXPECT_FALSE(parseLogLevel(""));
  EXPECT_EQ(parseLogFormat("json"), LogFormat::Json);
  EXPECT_EQ(parseLogFormat("text"), LogFormat::Text);
  EXPECT_FALSE(parseLogFormat("xml"));
}

}  // namespace
}  // namespace vem::cli
