#include <algorithm>
#include <amfrac/base/first_failure.h>
#include <amfrac/checkpoint/checkpoint_store.h>
#include <amfrac/parameters/input_error.h>
#include <chrono>
#include <cstdio>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <filesystem>
#include <functional>

namespace amfrac
{
  namespace
  {
    namespace fs = std::filesystem;
    using dealii::Utilities::int_to_string;

    std::string
    folder_name(const unsigned long number)
    {
      char name[64];
      std::snprintf(name, sizeof(name), "checkpoint-%08lu", number);
      return name;
    }

    std::string
    part_name(const unsigned int rank)
    {
      return "rank-" + int_to_string(rank, 4) + ".h5";
    }

    /** Run @p action on this rank; every rank learns the first failure
     * (with its rank) and throws it as @p Error. */
    template <typename Error>
    void
    collectively(const MPI_Comm comm, const std::function<void()> &action)
    {
      std::string failure;
      try
        {
          action();
        }
      catch (const std::exception &e)
        {
          failure = e.what();
          if (failure.empty())
            failure = "unknown error";
        }
      throw_first_failure<Error>(comm, failure, true);
    }

    void
    remove_or_throw(const fs::path &path)
    {
      std::error_code error;
      fs::remove_all(path, error);
      if (error)
        throw std::runtime_error("cannot remove '" + path.string()
                                 + "': " + error.message());
    }
  } // namespace



  CheckpointStore::CheckpointStore(const std::string &directory,
                                   const unsigned int keep,
                                   const MPI_Comm     comm)
    : directory(directory)
    , keep(keep)
    , comm(comm)
  {}



  std::vector<unsigned long>
  CheckpointStore::numbers(const std::string &directory)
  {
    std::vector<unsigned long> found;
    std::error_code            error;
    for (const auto &entry : fs::directory_iterator(directory, error))
      {
        const std::string name = entry.path().filename().string();
        const std::string stem = "checkpoint-";
        if (name.size() <= stem.size() || name.compare(0, stem.size(), stem)
            || !entry.is_directory())
          continue;
        const std::string digits = name.substr(stem.size());
        if (digits.find_first_not_of("0123456789") != std::string::npos)
          continue;
        found.push_back(std::stoul(digits));
      }
    std::sort(found.begin(), found.end());
    return found;
  }



  void
  CheckpointStore::clear() const
  {
    collectively<CollectiveError>(comm, [&]() {
      if (dealii::Utilities::MPI::this_mpi_process(comm) != 0
          || !fs::exists(directory))
        return;
      for (const auto &entry : fs::directory_iterator(directory))
        if (entry.path().filename().string().rfind("checkpoint-", 0) == 0)
          remove_or_throw(entry.path());
    });
  }



  std::string
  CheckpointStore::write(const unsigned long   number,
                         const CheckpointData &run,
                         const CheckpointData &rank_part) const
  {
    const unsigned int rank  = dealii::Utilities::MPI::this_mpi_process(comm);
    const fs::path     final = fs::path(directory) / folder_name(number);
    const fs::path     temporary = final.string() + ".tmp";
    collectively<CollectiveError>(comm, [&]() {
      if (rank != 0)
        return;
      remove_or_throw(temporary);
      fs::create_directories(temporary);
    });
    collectively<CollectiveError>(comm, [&]() {
      rank_part.write((temporary / part_name(rank)).string());
      if (rank == 0)
        run.write((temporary / "run.h5").string());
    });
    collectively<CollectiveError>(comm, [&]() {
      if (rank != 0)
        return;
      // An older checkpoint of the same number (a run resumed from an
      // earlier one) gives way; the rename itself is atomic.
      remove_or_throw(final);
      fs::rename(temporary, final);
      const auto complete = numbers(directory);
      for (std::size_t i = 0; i + keep < complete.size(); ++i)
        remove_or_throw(fs::path(directory) / folder_name(complete[i]));
      // Leftovers of a run killed while writing.
      for (const auto &entry : fs::directory_iterator(directory))
        {
          const std::string name = entry.path().filename().string();
          if (name.rfind("checkpoint-", 0) == 0 && name.size() > 4
              && name.compare(name.size() - 4, 4, ".tmp") == 0)
            remove_or_throw(entry.path());
        }
    });
    return final.string();
  }



  std::string
  CheckpointStore::newest(const std::string &directory)
  {
    if (fs::exists(fs::path(directory) / "run.h5"))
      return directory;
    const auto complete = numbers(directory);
    if (complete.empty())
      return "";
    return (fs::path(directory) / folder_name(complete.back())).string();
  }



  std::string
  CheckpointStore::newest(const std::string &directory, const MPI_Comm comm)
  {
    std::string folder;
    if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
      folder = newest(directory);
    return dealii::Utilities::MPI::broadcast(comm, folder, 0);
  }



  unsigned int
  CheckpointStore::remove_after(const unsigned long number) const
  {
    unsigned int removed = 0;
    collectively<CollectiveError>(comm, [&]() {
      if (dealii::Utilities::MPI::this_mpi_process(comm) != 0
          || !fs::exists(directory))
        return;
      for (const unsigned long n : numbers(directory))
        if (n > number)
          {
            remove_or_throw(fs::path(directory) / folder_name(n));
            ++removed;
          }
    });
    return dealii::Utilities::MPI::broadcast(comm, removed, 0);
  }



  CheckpointStore::Contents
  CheckpointStore::read(const std::string &folder, const MPI_Comm comm)
  {
    const auto start = std::chrono::steady_clock::now();
    Contents   contents;
    contents.folder = folder;
    collectively<InputError>(comm, [&]() {
      try
        {
          contents.run       = CheckpointData::read(folder + "/run.h5");
          const auto n_parts = contents.run.get_integer("ranks");
          for (unsigned int r = 0; r < n_parts; ++r)
            contents.parts.push_back(
              CheckpointData::read(folder + "/" + part_name(r)));
        }
      catch (const std::exception &e)
        {
          throw std::runtime_error(
            std::string("cannot resume from checkpoint '") + folder
            + "': " + e.what());
        }
    });
    contents.read_seconds
      = std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
    return contents;
  }
} // namespace amfrac
