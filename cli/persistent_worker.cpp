#include "cli/persistent_worker.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <climits>
#include <cerrno>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <streambuf>

#include "cli/commands.hpp"
#include "cli/diagnostic_output.hpp"
#include "compiler/json_text.hpp"
#include "compiler/literal.hpp"

namespace wg {

namespace {

// A response carries what its command printed, up to this much.
constexpr std::size_t kMaxOutputBytes = 1u << 20;
// One request may be this long; Bazel's are a command line, a few hundred bytes.
constexpr std::size_t kMaxRequestBytes = 16u << 20;

// Descriptors 1 and 2 point into a temporary file while a request runs, so that every
// line its command prints, whatever prints it, reaches the response and not the protocol.
class OutputCapture {
 public:
  OutputCapture() : file_(std::tmpfile()) {}
  ~OutputCapture() {
    if (file_) std::fclose(file_);
  }
  OutputCapture(const OutputCapture&) = delete;
  OutputCapture& operator=(const OutputCapture&) = delete;
  bool ok() const { return file_ != nullptr; }

  bool begin() {
    std::fflush(stdout);
    std::fflush(stderr);
    const int fd = ::fileno(file_);
    return ::ftruncate(fd, 0) == 0 && ::lseek(fd, 0, SEEK_SET) == 0 && ::dup2(fd, STDOUT_FILENO) >= 0 &&
           ::dup2(fd, STDERR_FILENO) >= 0;
  }

  // Points 1 and 2 back at `log` and returns what was printed.
  std::string end(int log) {
    std::fflush(stdout);
    std::fflush(stderr);
    ::dup2(log, STDOUT_FILENO);
    ::dup2(log, STDERR_FILENO);
    const int fd = ::fileno(file_);
    struct stat st {};
    if (::fstat(fd, &st) != 0) return "";
    const std::size_t size = static_cast<std::size_t>(st.st_size);
    std::string text(std::min(size, kMaxOutputBytes), '\0');
    std::size_t got = 0;
    while (got < text.size()) {
      const ssize_t n = ::pread(fd, text.data() + got, text.size() - got, static_cast<off_t>(got));
      if (n <= 0) break;
      got += static_cast<std::size_t>(n);
    }
    text.resize(got);
    if (size > got) {
      // Cut at a line's end, so no diagnostic is left half-said.
      const std::size_t lineEnd = text.rfind('\n');
      if (lineEnd != std::string::npos) text.resize(lineEnd + 1);
      text += "(" + std::to_string(size - text.size()) + " more bytes of output left out)\n";
    }
    return text;
  }

 private:
  std::FILE* file_;
};

// Stdin as the parser sees it: the end of input comes after `limit` bytes, so one
// endless request cannot take unbounded memory.
class BoundedInput : public std::streambuf {
 public:
  BoundedInput(std::streambuf* source, std::size_t limit) : source_(source), left_(limit) {}
  bool exhausted() const { return left_ == 0; }

 protected:
  int_type underflow() override { return left_ == 0 ? traits_type::eof() : source_->sgetc(); }
  int_type uflow() override {
    if (left_ == 0) return traits_type::eof();
    const int_type c = source_->sbumpc();
    if (c != traits_type::eof()) --left_;
    return c;
  }

 private:
  std::streambuf* source_;
  std::size_t left_;
};

enum class RequestRead { Ok, End, Malformed };

// One WorkRequest: Bazel writes them one after another, with or without whitespace.
RequestRead readRequest(std::istream& in, nlohmann::json& request, std::string& error) {
  int c = in.peek();
  while (c != std::char_traits<char>::eof() && std::isspace(c)) {
    in.get();
    c = in.peek();
  }
  if (c == std::char_traits<char>::eof()) return RequestRead::End;
  BoundedInput bounded(in.rdbuf(), kMaxRequestBytes);
  std::istream boundedIn(&bounded);
  try {
    boundedIn >> request;
  } catch (const nlohmann::json::exception& e) {
    error = bounded.exhausted() ? "it is longer than " + std::to_string(kMaxRequestBytes >> 20) + " MiB" : e.what();
    return RequestRead::Malformed;
  }
  if (request.is_object()) return RequestRead::Ok;
  error = "a work request must be a JSON object";
  return RequestRead::Malformed;
}

// The request's arguments; Bazel leaves out an empty list.
std::optional<std::vector<std::string>> requestArguments(const nlohmann::json& request, std::string& error) {
  std::vector<std::string> arguments;
  auto it = request.find("arguments");
  if (it == request.end()) return arguments;
  if (!it->is_array()) {
    error = "the request's \"arguments\" must be an array of strings";
    return std::nullopt;
  }
  for (const auto& a : *it) {
    if (!a.is_string()) {
      error = "the request's \"arguments\" must be an array of strings";
      return std::nullopt;
    }
    // A command line cannot hold NUL, and a path would end at it.
    if (a.get_ref<const std::string&>().find('\0') != std::string::npos) {
      error = "argument " + std::to_string(arguments.size() + 1) + " of the request holds a NUL character";
      return std::nullopt;
    }
    arguments.push_back(a.get<std::string>());
  }
  return arguments;
}

// The id its response must echo (0 when absent). Protobuf's JSON form writes an int32 as
// a number or as a string of one; an id that is neither cannot be echoed.
std::optional<std::int64_t> requestId(const nlohmann::json& request, std::string& error) {
  auto it = request.find("requestId");
  if (it == request.end()) return 0;
  std::optional<std::int64_t> id;
  if (it->is_number_unsigned()) {
    if (it->get<std::uint64_t>() <= INT32_MAX) id = it->get<std::int64_t>();
  } else if (it->is_number_integer()) {
    id = it->get<std::int64_t>();
  } else if (it->is_string()) {
    const std::string& text = it->get_ref<const std::string&>();
    std::int64_t value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec == std::errc() && end == text.data() + text.size() && !text.empty()) id = value;
  }
  if (id && *id >= INT32_MIN && *id <= INT32_MAX) return id;
  error = "the request's \"requestId\" must be an integer from -2147483648 to 2147483647 (a number or a string of one)";
  return std::nullopt;
}

// The command, with an escaping exception reported as main() reports it.
int runGuarded(const WorkerCommand& command, const std::vector<std::string>& arguments) {
  try {
    return command(arguments);
  } catch (const std::exception& e) {
    return internalError(&e);
  } catch (...) {
    return internalError(nullptr);
  }
}

bool writeAll(int fd, const std::string& text) {
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return true;
}

std::string responseLine(int exitCode, const std::string& output, std::int64_t id) {
  nlohmann::json response = {{"exitCode", exitCode}, {"output", output}, {"requestId", id}};
  // Output is bytes the command printed: invalid UTF-8 is replaced, not an exception.
  return jsonText(response) + "\n";
}

}  // namespace

int runPersistentWorker(const WorkerCommand& command) {
  // Responses go to the original stdout alone; stdout itself then points at stderr, the
  // worker's log, between requests.
  const int protocol = ::dup(STDOUT_FILENO);
  const int log = ::dup(STDERR_FILENO);
  OutputCapture capture;
  if (protocol < 0 || log < 0 || ::dup2(log, STDOUT_FILENO) < 0 || !capture.ok()) {
    std::perror("weathergen: error WG9900: internal error: the worker cannot set up its output");
    return kExitInternal;
  }
  for (std::size_t number = 1;; ++number) {
    nlohmann::json request;
    std::string error;
    const RequestRead read = readRequest(std::cin, request, error);
    if (read == RequestRead::End) return kExitOk;
    if (read == RequestRead::Malformed) {
      std::fprintf(stderr,
                   "weathergen: error WG9001: request %zu on stdin is not Bazel's JSON worker protocol: %s\n"
                   "  hint: the action needs the execution requirement \"requires-worker-protocol\": \"json\" "
                   "(Bazel's default is protobuf)\n",
                   number, quoteUserText(error, 300).c_str());
      return kExitUsage;
    }
    const std::optional<std::int64_t> id = requestId(request, error);
    std::string response;
    if (!id) {
      response = responseLine(kExitUsage, "weathergen: error WG9001: " + error + "\n", 0);
    } else if (auto arguments = requestArguments(request, error)) {
      if (!capture.begin()) {
        capture.end(log);
        std::perror("weathergen: error WG9900: internal error: the worker cannot capture a request's output");
        return kExitInternal;
      }
      const int exitCode = runGuarded(command, *arguments);
      response = responseLine(exitCode, capture.end(log), *id);
    } else {
      response = responseLine(kExitUsage, "weathergen: error WG9001: " + error + "\n", *id);
    }
    if (!writeAll(protocol, response)) return kExitInternal;
  }
}

}  // namespace wg
