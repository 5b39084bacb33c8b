// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "floodplane/io/output_rule.h"

#include <sys/stat.h>

#include <filesystem>
#include <map>
#include <system_error>
#include <utility>

namespace floodplane::io {
namespace {

namespace fs = std::filesystem;

// What makes two names one file: the file's device and inode when it exists, and its absolute
// path with "." and ".." and the links of the part that exists resolved (for files not written
// yet).
struct FileIdentity {
  bool exists = false;
  dev_t device = 0;
  ino_t inode = 0;
  std::string path;
};

FileIdentity identityOf(const std::string& name) {
  FileIdentity identity;
  struct stat status {};
  if (::stat(name.c_str(), &status) == 0) {
    identity.exists = true;
    identity.device = status.st_dev;
    identity.inode = status.st_ino;
  }
  std::error_code error;
  const fs::path canonical = fs::weakly_canonical(fs::absolute(name, error), error);
  if (!error) identity.path = canonical.lexically_normal().string();
  return identity;
}

}  // namespace

std::optional<std::string> outputCollision(const std::vector<std::string>& outputs,
                                           const std::vector<std::string>& inputs) {
  // Indexed both ways, so that a batch of thousands of inputs is checked in n log n.
  std::map<std::pair<dev_t, ino_t>, const std::string*> input_of_file;
  std::map<std::string, const std::string*> input_of_path;
  for (const std::string& input : inputs) {
    if (input.empty()) continue;
    const FileIdentity identity = identityOf(input);
    if (!identity.exists) continue;
    input_of_file.emplace(std::make_pair(identity.device, identity.inode), &input);
    if (!identity.path.empty()) input_of_path.emplace(identity.path, &input);
  }
  std::vector<std::pair<const std::string*, FileIdentity>> output_files;
  for (const std::string& output : outputs) {
    if (output.empty()) continue;
    FileIdentity identity = identityOf(output);
    const auto by_file = identity.exists ? input_of_file.find({identity.device, identity.inode}) : input_of_file.end();
    const auto by_path = input_of_path.find(identity.path);
    const std::string* input = by_file != input_of_file.end() ? by_file->second
                               : by_path != input_of_path.end() ? by_path->second
                                                                : nullptr;
    if (input) return "the output " + output + " would overwrite the input " + *input;
    output_files.emplace_back(&output, std::move(identity));
  }
  std::map<std::pair<dev_t, ino_t>, const std::string*> output_of_file;
  std::map<std::string, const std::string*> output_of_path;
  for (const auto& [output, identity] : output_files) {
    const std::string* earlier = nullptr;
    if (identity.exists) {
      const auto [at, inserted] = output_of_file.emplace(std::make_pair(identity.device, identity.inode), output);
      if (!inserted) earlier = at->second;
    }
    if (!earlier && !identity.path.empty()) {
      const auto [at, inserted] = output_of_path.emplace(identity.path, output);
      if (!inserted) earlier = at->second;
    }
    if (earlier) return "the outputs " + *earlier + " and " + *output + " are one file";
  }
  return std::nullopt;
}

}  // namespace floodplane::io
