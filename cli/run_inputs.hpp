// The files one run reads, known by identity: the device and inode each path names
// after its links are followed. Every command that writes (compile, import, render)
// checks each of its outputs here before it writes anything, so no output replaces an
// input under any spelling: "./g.json", a link, a linked folder, "out/..", a hard link.
#pragma once
#include <sys/types.h>

#include <filesystem>
#include <string>
#include <vector>

namespace wg {

// An output a run is about to write, and the option that named it ("-o", "--depfile",
// "--frames") for the message.
struct PlannedOutput {
  std::string option;
  std::filesystem::path path;
};

class RunInputs {
 public:
  // A path that does not exist (yet) is skipped: nothing can replace it.
  void add(const std::filesystem::path& input);
  void add(const std::vector<std::string>& inputs);
  void add(const std::vector<std::filesystem::path>& inputs);

  // "" when no output is an input; otherwise one line naming the first output that is,
  // the option that named it and the input it would replace.
  std::string checkOutputs(const std::vector<PlannedOutput>& outputs) const;

 private:
  struct Identity {
    dev_t device;
    ino_t inode;
    std::string path;  // as the run named it, for the message
  };
  std::vector<Identity> inputs_;
};

// "" when no output is a device, a FIFO or a socket (followed through links); otherwise
// one line naming the first and what it is. For the files a user names (render's
// pictures, compile's depfile): they are renamed into place, which would replace the
// node itself, so -o /dev/null run as root would leave a PNG where the device was.
// Files inside an output directory are the run's own and are replaced.
std::string checkNoSpecialFiles(const std::vector<PlannedOutput>& outputs);

}  // namespace wg
