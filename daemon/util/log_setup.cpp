#include "util/log_setup.h"

#include <time.h>

#include <array>
#include <chrono>
#include <cstdlib>
#include <utility>

#include <fmt/format.h>
#include <spdlog/pattern_formatter.h>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>
#include <nlohmann/json.hpp>

namespace vem::cli {
namespace {

constexpr std::array<std::pair<std::string_view, spdlog::level::level_enum>, 6> kLevels{{
    {"trace", spdlog::level::trace},
    {"debug", spdlog::level::debug},
    {"info", spdlog::level::info},
    {"warn", spdlog::level::warn},
    {"error", spdlog::level::err},
    {"off", spdlog::level::off},
}};

// spdlog's long level name ("warning", "error", "critical").
std::string_view levelText(spdlog::level::level_enum level) {
  const auto name = spdlog::level::to_string_view(level);
  return {name.data(), name.size()};
}

// "<N>": the sd-daemon prefix with the syslog priority of the level (sd-daemon.h: SD_ERR "<3>",
// SD_WARNING "<4>", SD_INFO "<6>", SD_DEBUG "<7>").
class JournalPriority final : public spdlog::custom_flag_formatter {
 public:
  void format(const spdlog::details::log_msg& msg, const std::tm&,
              spdlog::memory_buf_t& dest) override {
    int priority = 6;
    switch (msg.level) {
      case spdlog::level::trace:
      case spdlog::level::debug: priority = 7; break;
      case spdlog::level::info: priority = 6; break;
      case spdlog::level::warn: priority = 4; break;
      case spdlog::level::err: priority = 3; break;
      case spdlog::level::critical: priority = 2; break;
      default: break;
    }
    fmt::format_to(std::back_inserter(dest), "<{}>", priority);
  }
  [[nodiscard]] std::unique_ptr<custom_flag_formatter> clone() const override {
    return std::make_unique<JournalPriority>();
  }
};

// One JSON object per message (see the header).
class JsonLineFormatter final : public spdlog::formatter {
 public:
  void format(const spdlog::details::log_msg& msg, spdlog::memory_buf_t& dest) override {
    const auto sinceEpoch = msg.time.time_since_epoch();
    const std::time_t seconds =
        std::chrono::duration_cast<std::chrono::seconds>(sinceEpoch).count();
    const auto millis =
        std::chrono::duration_cast<std::chrono::milliseconds>(sinceEpoch).count() % 1000;
    std::tm utc{};
    ::gmtime_r(&seconds, &utc);
    const nlohmann::ordered_json line{
        {"time",
         fmt::format("{:04}-{:02}-{:02}T{:02}:{:02}:{:02}.{:03}Z", utc.tm_year + 1900,
                     utc.tm_mon + 1, utc.tm_mday, utc.tm_hour, utc.tm_min, utc.tm_sec, millis)},
        {"level", levelText(msg.level)},
        {"logger", std::string_view(msg.logger_name.data(), msg.logger_name.size())},
        {"message", std::string_view(msg.payload.data(), msg.payload.size())},
    };
    const std::string text =
        line.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
    dest.append(text.data(), text.data() + text.size());
    dest.push_back('\n');
  }
  [[nodiscard]] std::unique_ptr<spdlog::formatter> clone() const override {
    return std::make_unique<JsonLineFormatter>();
  }
};

}  // namespace

std::optional<spdlog::level::level_enum> parseLogLevel(std::string_view name) {
  for (const auto& [text, level] : kLevels) {
    if (text == name) return level;
  }
  return std::nullopt;
}

std::optional<LogFormat> parseLogFormat(std::string_view name) {
  if (name == "text") return LogFormat::Text;
  if (name == "json") return LogFormat::Json;
  return std::nullopt;
}

std::string_view logLevelName(spdlog::level::level_enum level) {
  for (const auto& [text, known] : kLevels) {
    if (known == level) return text;
  }
  return levelText(level);
}

std::string_view logFormatName(LogFormat format) {
  return format == LogFormat::Json ? "json" : "text";
}

bool underJournald() {
  const char* stream = std::getenv("JOURNAL_STREAM");
  return stream != nullptr && *stream != '\0';
}

std::unique_ptr<spdlog::formatter> makeLogFormatter(const LogOptions& options) {
  if (options.format == LogFormat::Json) return std::make_unique<JsonLineFormatter>();
  auto formatter = std::make_unique<spdlog::pattern_formatter>();
  if (options.journal) {
    formatter->add_flag<JournalPriority>('*').set_pattern("%*%l: %v");
  } else {
    formatter->set_pattern("%Y-%m-%d %H:%M:%S.%e %n %^%l%$: %v");
  }
  return formatter;
}

void setUpLogging(std::string_view toolName, const LogOptions& options) {
  const std::string name(toolName);
  spdlog::drop(name);
  auto logger = spdlog::stderr_color_mt(name);
  logger->set_formatter(makeLogFormatter(options));
  logger->set_level(options.level);
  spdlog::set_default_logger(std::move(logger));
}

}  // namespace vem::cli
