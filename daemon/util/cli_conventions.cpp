#include "util/cli_conventions.h"

#include <iostream>
#include <memory>
#include <sstream>
#include <vector>

namespace vem::cli {
namespace {

// CLI11 writes a choice map as "{a->1,b->2}" (a CheckedTransformer) or "{a,b}" (IsMember); a
// type name may carry several validator descriptions joined by " OR " / " AND ".
std::vector<std::string> choicesIn(std::string_view set) {
  std::vector<std::string> choices;
  std::string current;
  for (char c : set) {
    if (c == ',') {
      choices.push_back(current);
      current.clear();
    } else {
      current += c;
    }
  }
  choices.push_back(current);
  for (std::string& choice : choices) {
    if (auto arrow = choice.find("->"); arrow != std::string::npos) choice.resize(arrow);
  }
  return choices;
}

// An enum's default is captured as its number ("0"); the choice map ("{gl->0,...}") names it.
std::string defaultName(std::string_view cli11TypeName, const std::string& defaultValue) {
  const std::size_t open = cli11TypeName.find('{');
  const std::size_t close = cli11TypeName.find('}', open);
  if (open == std::string_view::npos || close == std::string_view::npos) return defaultValue;
  std::string set(cli11TypeName.substr(open + 1, close - open - 1));
  std::string pair;
  std::istringstream pairs(set);
  while (std::getline(pairs, pair, ',')) {
    const std::size_t arrow = pair.find("->");
    if (arrow != std::string::npos && pair.substr(arrow + 2) == defaultValue) return pair.substr(0, arrow);
  }
  return defaultValue;
}

std::string withoutFlagValues(const std::string& names) {
  std::string plain;
  bool inValue = false;
  for (char c : names) {
    if (c == '{') inValue = true;
    if (!inValue) plain += c;
    if (c == '}') inValue = false;
  }
  return plain;
}

class PlainFormatter : public CLI::Formatter {
 public:
  std::string make_option_name(const CLI::Option* opt, bool isPositional) const override {
    return withoutFlagValues(CLI::Formatter::make_option_name(opt, isPositional));
  }

  std::string make_option_opts(const CLI::Option* opt) const override {
    if (!opt->get_option_text().empty()) return " " + opt->get_option_text();
    std::ostringstream out;
    if (opt->get_type_size() != 0) {
      const std::string type = plainTypeName(opt->get_type_name());
      if (!type.empty()) out << " " << type;
      if (opt->get_expected_max() == CLI::detail::expected_max_vector_size) out << " ...";
      if (!opt->get_default_str().empty()) {
        out << " (default: " << defaultName(opt->get_type_name(), opt->get_default_str()) << ")";
      }
      if (opt->get_required()) out << " (required)";
    }
    if (!opt->get_needs().empty()) {
      out << " (needs";
      for (const CLI::Option* needed : opt->get_needs()) out << " " << needed->get_name();
      out << ")";
    }
    if (!opt->get_excludes().empty()) {
      out << " (not with";
      for (const CLI::Option* excluded : opt->get_excludes()) out << " " << excluded->get_name();
      out << ")";
    }
    return out.str();
  }
};

void applyTo(CLI::App& app, const std::shared_ptr<CLI::FormatterBase>& formatter, const std::string& tool) {
  app.formatter(formatter);
  // Last on the page, below the tool's own footer (examples). A subcommand may have copied its
  // parent's footer when it was made, the line included: it is added once.
  const std::string footer = app.get_footer();
  if (footer.find(kExitStatusHelp) == std::string::npos) {
    app.footer(footer.empty() ? std::string(kExitStatusHelp) : footer + "\n\n" + std::string(kExitStatusHelp));
  }
  app.failure_message([tool](const CLI::App* failed, const CLI::Error& e) {
    // CLI11 hands over the top app; the subcommands chosen so far say whose help to read.
    std::string command;
    for (const CLI::App* a = failed; !a->get_subcommands().empty();) {
      a = a->get_subcommands().front();
      command += " " + a->get_name();
    }
    return tool + ": error: " + e.what() + " (see '" + tool + command + " --help')\n";
  });
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) {
    applyTo(*sub, formatter, tool);
  }
}

}  // namespace

std::string plainTypeName(std::string_view cli11TypeName) {
  const std::size_t open = cli11TypeName.find('{');
  const std::size_t close = cli11TypeName.find('}', open);
  if (open == std::string_view::npos || close == std::string_view::npos) {
    return std::string(cli11TypeName);
  }
  std::string plain;
  for (const std::string& choice : choicesIn(cli11TypeName.substr(open + 1, close - open - 1))) {
    if (!plain.empty()) plain += '|';
    plain += choice;
  }
  return plain;
}

void applyConventions(CLI::App& app, std::string_view toolName) {
  auto formatter = std::make_shared<PlainFormatter>();
  formatter->column_width(34);
  applyTo(app, formatter, std::string(toolName));
}

int exitStatusFor(const CLI::App& app, const CLI::ParseError& e, std::ostream& out, std::ostream& err) {
  const int cli11Code = app.exit(e, out, err);
  return cli11Code == 0 ? kExitSuccess : kExitUsage;
}

int exitStatusFor(const CLI::App& app, const CLI::ParseError& e) {
  return exitStatusFor(app, e, std::cout, std::cerr);
}

}  // namespace vem::cli
