#include <amfrac/postprocess/atomic_file.h>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <unistd.h>

namespace amfrac
{
  void
  rename_or_throw(const std::string &from, const std::string &to)
  {
    std::error_code error;
    std::filesystem::rename(from, to, error);
    if (error)
      throw std::runtime_error("cannot rename '" + from + "' to '" + to
                               + "': " + error.message());
  }



  void
  write_atomically(const std::string                         &path,
                   const std::function<void(std::ostream &)> &writer)
  {
    const std::string temporary = path + ".tmp" + std::to_string(::getpid());
    try
      {
        std::ofstream out(temporary);
        if (!out)
          throw std::runtime_error("cannot write '" + temporary + "'");
        writer(out);
        out.flush();
        if (!out)
          throw std::runtime_error("writing '" + path + "' failed");
        out.close();
        rename_or_throw(temporary, path);
      }
    catch (...)
      {
        std::remove(temporary.c_str());
        throw;
      }
  }
} // namespace amfrac
