// The files a command writes, all or none, and never over one it read.  Each output is
// written to a temporary name beside its target (same directory, same extension, so that
// the rename stays on one file system and OpenImageIO still knows the format); commit()
// renames them all into place, and if one rename fails the ones done are undone.  An output
// that would replace an input (compared as files: through links and any spelling of the
// path), another output or a directory is refused when it is staged, before anything is
// written.  A device, a FIFO or "-" named as an output is written as a stream when the set
// is committed, before any file is renamed (util/output_path.h).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "util/output_path.h"
#include "util/result.h"

namespace mirage {

class OutputSet {
  public:
    /// `inputs`: every file the command read (the scene and each file it includes); none of
    /// them may be replaced.
    explicit OutputSet(std::vector<std::string> inputs = {});
    ~OutputSet();  // removes what was staged and not committed
    OutputSet(const OutputSet&) = delete;
    OutputSet& operator=(const OutputSet&) = delete;

    /// More files the command reads.
    void protect(const std::vector<std::string>& inputs);

    /// Whether `path` may be staged: not an input, not staged already, not a directory.
    Status check(const std::string& path) const;

    /// Reserves `path` for an output (check() first) and returns the temporary name to write
    /// it to.
    Result<std::string> stage(const std::string& path);

    /// Takes `temporary`, a file written already, as the content of `target` (check() first):
    /// for outputs written elsewhere (a staging directory) and renamed with the rest.
    Status adopt(const std::string& temporary, const std::string& target);

    /// Stages `path` and writes `content` to its temporary name.
    Status write_text(const std::string& path, std::string_view content);

    /// Renames every staged file into place: all of them, or, when one fails, none (the
    /// targets renamed already get back what they held).  The message names the file.
    Status commit();

    /// A staging folder for outputs written under a folder of their own (`out_dir`), at their
    /// paths relative to it: `out_dir/.staging-<pid>`, made afresh and removed with the set.
    /// Returns its path.
    Result<std::string> make_staging_folder(const std::string& out_dir);

    /// Adopts every file under the staging folder as the output at the same path below
    /// `out_dir` (each checked as adopt() checks: none may replace an input), then commits
    /// the set.
    Status commit_staging_folder();

    /// The targets staged so far, in order.
    std::vector<std::string> targets() const;

  private:
    struct Staged {
        OutputPath out;
        std::string temporary;
    };
    std::vector<std::string> inputs_;
    std::vector<Staged> staged_;
    std::string staging_folder_, staging_out_dir_;  // make_staging_folder's
};

}  // namespace mirage
