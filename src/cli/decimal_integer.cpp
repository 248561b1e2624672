#include "cli/decimal_integer.hpp"

#include <algorithm>
#include <cctype>
#include <string>

namespace swarmagg::cli {

CLI::Validator decimal_integer(bool signed_option) {
  return CLI::Validator(
      [signed_option](std::string& value) -> std::string {
        const std::size_t sign = signed_option && value.starts_with('-') ? 1 : 0;
        const bool digits_only =
            value.size() > sign &&
            std::all_of(value.begin() + static_cast<std::ptrdiff_t>(sign), value.end(),
                        [](unsigned char c) { return std::isdigit(c) != 0; });
        if (!digits_only) return "expected a whole number in decimal digits, got '" + value + "'";
        const std::size_t first_kept =
            std::min(value.find_first_not_of('0', sign), value.size() - 1);
        value.erase(sign, first_kept - sign);
        return "";
      },
      "");
}

void read_integers_in_decimal(CLI::App& app) {
  for (CLI::App* command : app.get_subcommands({})) {
    for (CLI::Option* option : command->get_options()) {
      // "INT", or "INT:..." once a check has added its description.
      const std::string type_name = option->get_type_name();
      const std::string type = type_name.substr(0, type_name.find_first_of(": "));
      if (type == "INT" || type == "UINT") option->transform(decimal_integer(type == "INT"));
    }
  }
}

}  // namespace swarmagg::cli
