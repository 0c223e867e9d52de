// Logging set-up for the vemcast tools, in one place (vemd first; vemtool, vemcalib and vemview
// may adopt it): one spdlog logger on stderr, named after the tool, made the default logger.
//
// - Level: trace|debug|info|warn|error|off ("--log-level"); "--quiet" is warn.
// - Text format: "2026-12-03 14:57:37.141 vemd warning: ..." (colour when stderr is a terminal).
//   Under journald (JOURNAL_STREAM set: systemd connected stderr to the journal) without a time
//   of its own, which the journal adds, and with the sd-daemon level prefix "<4>" (sd-daemon.h,
//   syslog priorities) that journald reads, so `journalctl -p warning` filters vemd's lines.
// - JSON format: one object per line, {"time":"2026-12-03T14:57:37.141Z","level":"warning",
//   "logger":"vemd","message":"..."}, serialized by nlohmann::json (quotes, newlines and control
//   bytes escaped; invalid UTF-8 replaced), so every line parses whatever the message holds.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include <spdlog/common.h>
#include <spdlog/formatter.h>

namespace vem::cli {

enum class LogFormat { Text, Json };

struct LogOptions {
  spdlog::level::level_enum level = spdlog::level::info;
  LogFormat format = LogFormat::Text;
  bool journal = false;  // stderr goes to journald (underJournald())
};

// "trace|debug|info|warn|error|off", for help and messages.
inline constexpr std::string_view kLogLevelChoices = "trace|debug|info|warn|error|off";
inline constexpr std::string_view kLogFormatChoices = "text|json";

// A name of kLogLevelChoices; nullopt for anything else.
[[nodiscard]] std::optional<spdlog::level::level_enum> parseLogLevel(std::string_view name);
[[nodiscard]] std::optional<LogFormat> parseLogFormat(std::string_view name);
[[nodiscard]] std::string_view logLevelName(spdlog::level::level_enum level);  // "warn"
[[nodiscard]] std::string_view logFormatName(LogFormat format);                // "json"

// True when the environment says stderr is the journal's (JOURNAL_STREAM is set).
[[nodiscard]] bool underJournald();

// The formatter setUpLogging uses for these options (exposed for tests).
[[nodiscard]] std::unique_ptr<spdlog::formatter> makeLogFormatter(const LogOptions& options);

// Replaces the default logger with a stderr logger named `toolName`, formatted and filtered as
// `options` say.
void setUpLogging(std::string_view toolName, const LogOptions& options);

}  // namespace vem::cli
