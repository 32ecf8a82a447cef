#include "usage_messages.hpp"

#include <optional>
#include <string_view>
#include <vector>

namespace lbmshape::cli {
namespace {

// The part of `message` after `prefix`, or nothing.
std::optional<std::string> after(const std::string& message, std::string_view prefix)
{
  if (!message.starts_with(prefix)) return std::nullopt;
  return message.substr(prefix.size());
}

std::vector<std::string> words(const std::string& text)
{
  std::vector<std::string> out;
  std::string word;
  for (char c : text) {
    if (c == ' ') {
      if (!word.empty()) out.push_back(word);
      word.clear();
    } else {
      word += c;
    }
  }
  if (!word.empty()) out.push_back(word);
  return out;
}

std::string quotedList(const std::vector<std::string>& items)
{
  std::string out;
  for (size_t i = 0; i < items.size(); ++i) out += (i ? ", '" : "'") + items[i] + "'";
  return out;
}

// "a whole number" for an option CLI11 converts to an integer, "a number"
// for a floating one.
std::string kindOfValue(const CLI::App& command, const std::string& name)
{
  const CLI::Option* option = command.get_option_no_throw(name);
  const std::string type = option ? option->get_type_name() : std::string();
  if (type.starts_with("INT") || type.starts_with("UINT")) return "a whole number";
  if (type.starts_with("FLOAT")) return "a number";
  return "a value it takes";
}

}  // namespace

std::string plainParseError(const CLI::App& app, const CLI::ParseError& e)
{
  const auto given = app.get_subcommands();
  const CLI::App& command = given.empty() ? app : *given.front();
  const std::string message = e.what();
  if (auto rest = after(message, "Could not convert: ")) {  // "--res = 1e2"
    const size_t equals = rest->find(" = ");
    if (equals != std::string::npos) {
      const std::string name = rest->substr(0, equals), value = rest->substr(equals + 3);
      return name + ": '" + value + "' is not " + kindOfValue(command, name);
    }
  }
  for (std::string_view prefix :
       {"The following argument was not expected: ", "The following arguments were not expected: "})
    if (auto rest = after(message, prefix)) {
      const std::vector<std::string> given = words(*rest);
      if (!given.empty() && given.size() == 1 && given[0].starts_with("-"))
        return "unknown option " + quotedList(given);
      return (given.size() == 1 ? "unexpected argument " : "unexpected arguments ") + quotedList(given);
    }
  if (message.ends_with(" is required")) return "missing argument '" + message.substr(0, message.size() - 12) + "'";
  if (const size_t colon = message.find(": 1 required "); colon != std::string::npos && message.ends_with(" missing"))
    return message.substr(0, colon) + ": its value is missing";
  return message;
}

}  // namespace lbmshape::cli
