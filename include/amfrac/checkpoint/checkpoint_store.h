#pragma once

#include <amfrac/checkpoint/checkpoint_data.h>
#include <mpi.h>
#include <string>
#include <vector>

namespace amfrac
{
  /**
   * The checkpoints of a run in one folder. Checkpoint n is the folder
   * `checkpoint-<n>` holding `run.h5` (rank 0: the parameters, the run's
   * counters and tables) and `rank-<r>.h5` (each rank's part of the
   * fields and histories). It is written as `checkpoint-<n>.tmp` and
   * renamed once every file is complete, so a folder without the suffix is
   * always whole: a crash while writing leaves the previous checkpoints
   * as they were.
   */
  class CheckpointStore
  {
  public:
    CheckpointStore(const std::string &directory,
                    const unsigned int keep,
                    const MPI_Comm     comm);

    /** Delete every checkpoint in the folder (a run that starts from the
     * beginning must not leave older checkpoints to resume from).
     * Collective. */
    void
    clear() const;

    /** Write checkpoint @p number: @p run from rank 0, @p rank_part from
     * every rank; then delete all but the newest Keep. Returns the
     * folder. Collective; throws CollectiveError on every rank if any
     * rank fails. */
    std::string
    write(const unsigned long   number,
          const CheckpointData &run,
          const CheckpointData &rank_part) const;

    /** The newest complete checkpoint folder in @p directory, or @p
     * directory itself if it is a checkpoint; empty if there is none. */
    static std::string
    newest(const std::string &directory);

    /** The same, decided by rank 0 for all ranks (collective). */
    static std::string
    newest(const std::string &directory, const MPI_Comm comm);

    /** Delete the checkpoints numbered above @p number (a run resumed
     * from an older checkpoint discards the future it had); returns how
     * many. Collective. */
    unsigned int
    remove_after(const unsigned long number) const;

    /** A checkpoint as read back: rank 0's run file and the parts of all
     * ranks that wrote it (any number of ranks may read it). */
    struct Contents
    {
      std::string                 folder;
      CheckpointData              run;
      std::vector<CheckpointData> parts;
      /** Wall time of read() [s]. */
      double read_seconds = 0;
    };

    /** Read and verify @p folder. Collective: every rank reads every
     * file; an error on any rank throws InputError on all, naming the
     * file. */
    static Contents
    read(const std::string &folder, const MPI_Comm comm);

  private:
    const std::string  directory;
    const unsigned int keep;
    const MPI_Comm     comm;

    /** The numbers of the complete checkpoints in the folder, ascending. */
    static std::vector<unsigned long>
    numbers(const std::string &directory);
  };
} // namespace amfrac
