// Folders a command makes for its outputs, taken away again when it fails: a refused or
// failed run leaves no empty folder behind.  Only folders this run made are removed, and
// only while they are empty (another run writing into the same new folder keeps it).
#pragma once

#include <string>
#include <vector>

#include "util/result.h"

namespace mirage {

class NewDirectories {
  public:
    NewDirectories() = default;
    ~NewDirectories();  // removes the empty folders made, unless kept
    NewDirectories(const NewDirectories&) = delete;
    NewDirectories& operator=(const NewDirectories&) = delete;

    /// Makes `dir` and the folders above it that are missing; an error names it.
    Status make(const std::string& dir);

    /// The folders stay (the command succeeded, or wrote what must be kept).
    void keep() { made_.clear(); }

  private:
    std::vector<std::string> made_;  // outermost first
};

}  // namespace mirage
