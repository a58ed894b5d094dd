#pragma once
// A command's output written as one set (issue 13, class 4): the command
// writes every file into a staging folder, and only a command that returns
// (exit 0, or 3: a run that stopped, its history and summary describing
// it) publishes it: the files of its OutputSet in --out that this run did
// not produce are removed, the new ones moved in; files of no set are left
// alone. A command that throws (exit 2, 1, 3 before any run's files, an
// interruption: 130, 143) or returns 1 leaves --out as it was: the staging
// folder is removed, and so is every directory the command created and
// left empty.
//
// The staging folder is DIR/.rsi-stage-PID, inside --out rather than
// beside it: it is then on the same filesystem (rename(2) is atomic and
// never copies), it needs no write access to --out's parent, and the lock
// that guards --out (OutputLock) guards it too, so a folder left by a
// killed run is known stale and removed by the next run that locks DIR.
//
// Publishing is renames within one filesystem, in the set's order
// (output_sets.hpp): the old entries go to DIR/.rsi-old-PID (descriptions
// first), then the new ones come in (data first), then both hidden folders
// are removed. A process killed in between leaves hidden folders for the
// next run to remove and never a summary, convergence table or report
// beside data it does not describe.

#include <optional>
#include <string>
#include <vector>

#include "output_files.hpp"
#include "output_lock.hpp"
#include "output_sets.hpp"

namespace rsi {

class StagedOutput {
public:
  /// Abandons `output` when it is destroyed during the unwinding of an
  /// exception (a scope guard): for a command that must clean --out before
  /// something else its unwinding does (MPI_Finalize, mpi_session.hpp).
  class AbandonOnThrow {
  public:
    explicit AbandonOnThrow(StagedOutput& output);
    ~AbandonOnThrow();
    AbandonOnThrow(const AbandonOnThrow&) = delete;
    AbandonOnThrow& operator=(const AbandonOnThrow&) = delete;

  private:
    StagedOutput& m_output;
    int m_exceptions; ///< std::uncaught_exceptions() at construction
  };

  StagedOutput() = default;
  /// Abandons an unpublished output (see abandon).
  ~StagedOutput();
  StagedOutput(const StagedOutput&) = delete;
  StagedOutput& operator=(const StagedOutput&) = delete;

  /// Creates `out` if missing (OutputDirectories::make), locks it, removes
  /// staging folders of killed runs, and creates the staging folder; returns
  /// it: the command writes its whole `set` there. Throws OutputError naming
  /// `option` (not creatable, not writable, another run holds the lock).
  std::string open(const std::string& out, const std::string& option, const OutputSet& set);
  /// Creates the folder `path` (inside the staging folder) and its parents;
  /// throws OutputError.
  void make(const std::string& path);
  /// Replaces the set in --out by the staged one, then unlocks. Nothing to
  /// do if open was never called (calibrate). Throws OutputError when a
  /// rename fails, std::logic_error if the staging folder holds a file no
  /// entry of the set names (a command writing outside its set).
  void publish();
  /// Removes the staging folder and the lock file, unlocks, and removes the
  /// directories open created that are empty: --out as it was. Never throws
  /// (it runs during unwinding).
  void abandon() noexcept;
  /// Prints `line` (a "wrote DIR/..." line, with its newline) on stdout
  /// once the set is published, never if it is abandoned: no line claims a
  /// file that is not there. Printed at once when nothing is staged.
  void announce(const std::string& line);
  /// `message` with the staging folder named as the --out path the user
  /// gave (the staging folder is removed before the message is read);
  /// `message` itself when nothing is staged.
  std::string shown(const std::string& message) const;

private:
  OutputDirectories m_directories;
  std::optional<OutputLock> m_lock;
  std::string m_out;
  std::string m_option;
  std::string m_staging; ///< empty: not open, or already published or abandoned
  std::string m_abandoned; ///< the staging folder abandon() removed, for shown()
  OutputSet m_set;
  std::vector<std::string> m_announced; ///< lines printed by publish()
};

} // namespace rsi
