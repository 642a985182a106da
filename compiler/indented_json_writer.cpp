#include "compiler/indented_json_writer.hpp"

#include <nlohmann/json.hpp>

#include "compiler/json_text.hpp"

namespace wg {

namespace {

// Bytes nlohmann writes as they are: printable ASCII other than '"' and '\'.
bool writtenAsIs(std::string_view text) {
  for (unsigned char c : text)
    if (c < 0x20 || c >= 0x7F || c == '"' || c == '\\') return false;
  return true;
}

void appendString(std::string& out, std::string_view value) {
  if (writtenAsIs(value)) {
    out += '"';
    out += value;
    out += '"';
    return;
  }
  out += jsonText(nlohmann::json(std::string(value)));
}

}  // namespace

void IndentedJsonWriter::beforeValue() {
  if (afterKey_) {
    afterKey_ = false;
    return;
  }
  if (levelEmpty_.empty()) return;  // the document's root
  out_ += levelEmpty_.back() ? "\n" : ",\n";
  levelEmpty_.back() = false;
  out_.append(2 * levelEmpty_.size(), ' ');
}

void IndentedJsonWriter::open(char bracket) {
  beforeValue();
  out_ += bracket;
  levelEmpty_.push_back(true);
}

void IndentedJsonWriter::close(char bracket) {
  const bool empty = levelEmpty_.back();
  levelEmpty_.pop_back();
  if (!empty) {
    out_ += '\n';
    out_.append(2 * levelEmpty_.size(), ' ');
  }
  out_ += bracket;
}

void IndentedJsonWriter::beginObject() { open('{'); }
void IndentedJsonWriter::endObject() { close('}'); }
void IndentedJsonWriter::beginArray() { open('['); }
void IndentedJsonWriter::endArray() { close(']'); }

IndentedJsonWriter& IndentedJsonWriter::key(std::string_view name) {
  beforeValue();
  appendString(out_, name);
  out_ += ": ";
  afterKey_ = true;
  return *this;
}

void IndentedJsonWriter::text(std::string_view value) {
  beforeValue();
  appendString(out_, value);
}

void IndentedJsonWriter::boolean(bool value) {
  beforeValue();
  out_ += value ? "true" : "false";
}

void IndentedJsonWriter::integer(std::int64_t value) {
  beforeValue();
  out_ += std::to_string(value);
}

void IndentedJsonWriter::number(double value) {
  beforeValue();
  out_ += nlohmann::json(value).dump();
}

void IndentedJsonWriter::json(const nlohmann::json& value) {
  if (value.is_object()) {
    beginObject();
    for (const auto& [name, item] : value.items()) {
      key(name);
      json(item);
    }
    endObject();
  } else if (value.is_array()) {
    beginArray();
    for (const auto& item : value) json(item);
    endArray();
  } else if (value.is_string()) {
    text(value.get_ref<const std::string&>());
  } else {
    beforeValue();
    out_ += jsonText(value);
  }
}

std::string IndentedJsonWriter::finish() {
  out_ += '\n';
  return std::move(out_);
}

}  // namespace wg
