#pragma once

#include <mpi.h>
#include <string>
#include <vector>

namespace amfrac
{
  /**
   * What the amfrac executable does with its command line (@p arguments
   * without the program's name), MPI already initialized: the options of
   * `amfrac --help`, or the run of a parameter file or of a checkpoint. An
   * error is one line on rank 0's stderr naming the parameter or the cause;
   * the return value is the exit status (0 done, 1 bad input or a failed
   * run, 2 usage, 75 stopped with a checkpoint). A library function so
   * that the bad-input test can put many files through it in one process.
   */
  int
  command_line(const std::vector<std::string> &arguments, MPI_Comm comm);
} // namespace amfrac
