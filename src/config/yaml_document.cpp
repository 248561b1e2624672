#include "config/yaml_document.hpp"

#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/eventhandler.h>

#include <sstream>
#include <vector>

#include "core/errors.hpp"

namespace swarmagg {

// Where a value came from, for messages: "file:line:column" or "--set".
std::string where_mark(const std::string& source, const YAML::Mark& mark) {
  if (mark.is_null()) return source;
  return source + ":" + std::to_string(mark.line + 1) + ":" + std::to_string(mark.column + 1);
}

std::string syntax_error(const std::string& source, const YAML::Mark& mark,
                         const std::string& what) {
  return where_mark(source, mark) + ": YAML syntax error: " + what;
}

namespace {

// Where each document of a YAML text starts and whether it holds anything but null.
class DocumentStarts final : public YAML::EventHandler {
 public:
  struct Document {
    YAML::Mark start;
    bool empty = true;
  };

  const std::vector<Document>& documents() const { return documents_; }
  // yaml-cpp 0.7 does not consume a ',' that starts a document: it reports an empty document
  // at the same place again and again (YAML::LoadAll never returns).
  bool stuck() const {
    const auto n = documents_.size();
    return n >= 2 && documents_[n - 1].start.pos == documents_[n - 2].start.pos;
  }

  void OnDocumentStart(const YAML::Mark& mark) override { documents_.push_back({mark, true}); }
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark&, YAML::anchor_t) override {}
  void OnAlias(const YAML::Mark&, YAML::anchor_t) override { content(); }
  void OnScalar(const YAML::Mark&, const std::string&, YAML::anchor_t,
                const std::string&) override {
    content();
  }
  void OnSequenceStart(const YAML::Mark&, const std::string&, YAML::anchor_t,
                       YAML::EmitterStyle::value) override {
    content();
  }
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark&, const std::string&, YAML::anchor_t,
                  YAML::EmitterStyle::value) override {
    content();
  }
  void OnMapEnd() override {}

 private:
  void content() { documents_.back().empty = false; }

  std::vector<Document> documents_;
};

// YAML::Load would silently drop everything after a second '---'. Empty documents (a stray
// '---' at the end) lose nothing and are let through.
void check_one_document(const std::string& text, const std::string& source,
                        const std::string& kind) {
  std::istringstream in(text);
  YAML::Parser parser(in);
  DocumentStarts starts;
  while (parser.HandleNextDocument(starts)) {
    const auto& last = starts.documents().back();
    if (starts.stuck()) {
      const auto at = static_cast<std::size_t>(last.start.pos);
      const std::string what = at < text.size() ? std::string(1, text[at]) : "end of file";
      throw InputError(syntax_error(source, last.start, "unexpected '" + what + "'"));
    }
    if (starts.documents().size() > 1 && !last.empty) {
      throw InputError(where_mark(source, last.start) + ": a second YAML document starts here; " +
                       kind + " is one YAML document");
    }
  }
}

}  // namespace

YAML::Node parse_one_yaml_document(const std::string& text, const std::string& source,
                                   const std::string& what) {
  try {
    check_one_document(text, source, what);
    return YAML::Load(text);
  } catch (const YAML::DeepRecursion& e) {
    // yaml-cpp's own message for this is "bad file".
    throw InputError(syntax_error(
        source, e.mark, "nested more than " + std::to_string(e.depth() - 1) + " levels deep"));
  } catch (const YAML::ParserException& e) {
    throw InputError(syntax_error(source, e.mark, e.msg));
  }
}

}  // namespace swarmagg
