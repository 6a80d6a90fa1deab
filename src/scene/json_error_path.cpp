#include "scene/json_error_path.hpp"

#include <vector>

#include <nlohmann/json.hpp>

namespace sl {

namespace {

// A SAX handler that keeps only the path to the current value.
class PathTracker : public nlohmann::json_sax<nlohmann::json> {
 public:
  std::string failedAt;

  bool null() override { return value(); }
  bool boolean(bool) override { return value(); }
  bool number_integer(number_integer_t) override { return value(); }
  bool number_unsigned(number_unsigned_t) override { return value(); }
  bool number_float(number_float_t, const string_t&) override { return value(); }
  bool string(string_t&) override { return value(); }
  bool binary(binary_t&) override { return value(); }
  bool start_object(std::size_t) override { return open(Level{true, "", -1}); }
  bool end_object() override { return close(); }
  bool start_array(std::size_t) override { return open(Level{false, "", -1}); }
  bool end_array() override { return close(); }
  bool key(string_t& name) override {
    levels_.back().key = name;
    return true;
  }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override {
    failedAt = path();
    return false;
  }

 private:
  struct Level {
    bool isObject;
    std::string key;
    long index;
  };
  std::vector<Level> levels_;

  // Called before a value is stored: arrays count their elements.
  void enterValue() {
    if (!levels_.empty() && !levels_.back().isObject) ++levels_.back().index;
  }
  bool value() {
    enterValue();
    return true;
  }
  bool open(Level level) {
    enterValue();
    levels_.push_back(level);
    return true;
  }
  bool close() {
    levels_.pop_back();
    return true;
  }
  std::string path() const {
    std::string text;
    for (const Level& level : levels_) {
      if (level.isObject) {
        if (level.key.empty()) continue;
        if (!text.empty()) text += '.';
        text += level.key;
      } else if (level.index >= 0) {
        text.append(1, '[').append(std::to_string(level.index)).append(1, ']');
      }
    }
    return text;
  }
};

}  // namespace

std::string jsonPathOfParseError(const std::string& text) {
  PathTracker tracker;
  nlohmann::json::sax_parse(text, &tracker, nlohmann::json::input_format_t::json, false);
  return tracker.failedAt;
}

}  // namespace sl
