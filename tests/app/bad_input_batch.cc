// The bad-input cases of app/bad_input.sh in one process: each CASE.prm
// goes through amfrac::command_line(), what the amfrac executable runs, with
// stdout and stderr sent to CASE.stdout and CASE.stderr; its exit status
// goes to CASE.status, and the first file it left in the folder `out` (the
// cases' Output/Directory) to CASE.written, before `out` is removed. A new
// process per case spent 0.4 s starting up (Open MPI and the ~200 shared
// libraries of deal.II) of the 0.41 s a case takes; the script checks the
// files as it checked the processes.
// usage: app_bad_input_batch CASE... (in the cases' folder)
#include <amfrac/app/command_line.h>
#include <cstdio>
#include <deal.II/base/mpi.h>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <unistd.h>

namespace
{
  /** Sends the file descriptor @p fd to @p file while it lives. */
  class Redirect
  {
  public:
    Redirect(const int fd, const std::string &file)
      : fd(fd)
      , saved(dup(fd))
    {
      const int target = open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      dup2(target, fd);
      close(target);
    }
    ~Redirect()
    {
      dup2(saved, fd);
      close(saved);
    }

  private:
    int fd, saved;
  };

  /** The first regular file under @p folder, or "". */
  std::string
  first_file(const std::filesystem::path &folder)
  {
    if (!std::filesystem::exists(folder))
      return "";
    for (const auto &entry :
         std::filesystem::recursive_directory_iterator(folder))
      if (entry.is_regular_file())
        return entry.path().string();
    return "";
  }

  int
  run_case(const std::string &name)
  {
    int status;
    {
      Redirect out(STDOUT_FILENO, name + ".stdout");
      Redirect err(STDERR_FILENO, name + ".stderr");
      status = amfrac::command_line({name + ".prm"}, MPI_COMM_WORLD);
      std::cout.flush();
      std::cerr.flush();
      std::fflush(nullptr);
    }
    return status;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  for (int i = 1; i < argc; ++i)
    {
      const std::string name = argv[i];
      std::ofstream(name + ".status") << run_case(name) << "\n";
      std::ofstream(name + ".written") << first_file("out");
      std::filesystem::remove_all("out");
    }
  return 0;
}
