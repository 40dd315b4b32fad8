#include <amfrac/checkpoint/checkpoint_data.h>
#include <hdf5.h>
#include <stdexcept>
#include <utility>

namespace amfrac
{
  namespace
  {
    const char *format_name = "amfrac checkpoint";

    /** FNV-1a, 64 bit: cheap, and any flipped or lost byte changes it. */
    std::uint64_t
    checksum(const void *data, const std::size_t bytes)
    {
      std::uint64_t hash   = 1469598103934665603ull;
      const auto   *bytes_ = static_cast<const unsigned char *>(data);
      for (std::size_t i = 0; i < bytes; ++i)
        hash = (hash ^ bytes_[i]) * 1099511628211ull;
      return hash;
    }

    /** An HDF5 handle closed by its own function on every exit path. */
    class Handle
    {
    public:
      Handle(const hid_t id, herr_t (*close)(hid_t), const std::string &what)
        : id(id)
        , close(close)
      {
        if (id < 0)
          throw std::runtime_error(what);
      }
      ~Handle()
      {
        if (open)
          close(id);
      }
      /** Close now and report failure (a file's last data is written
       * here). */
      void
      close_or_throw(const std::string &what)
      {
        open = false;
        if (close(id) < 0)
          throw std::runtime_error(what);
      }
      Handle(const Handle &) = delete;
      Handle &
      operator=(const Handle &)
        = delete;
      operator hid_t() const
      {
        return id;
      }

    private:
      const hid_t id;
      herr_t (*close)(hid_t);
      bool open = true;
    };

    void
    check(const herr_t status, const std::string &what)
    {
      if (status < 0)
        throw std::runtime_error(what);
    }

    template <typename T>
    void
    write_array(const hid_t        group,
                const std::string &name,
                const hid_t        type,
                const T           *data,
                const std::size_t  n,
                const std::string &path)
    {
      const std::string what
        = "cannot write dataset '" + name + "' to '" + path + "'";
      const hsize_t dims[1] = {n};
      Handle        space(H5Screate_simple(1, dims, nullptr), H5Sclose, what);
      Handle        set(H5Dcreate2(group,
                            name.c_str(),
                            type,
                            space,
                            H5P_DEFAULT,
                            H5P_DEFAULT,
                            H5P_DEFAULT),
                 H5Dclose,
                 what);
      if (n > 0)
        check(H5Dwrite(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), what);
      const std::uint64_t sum = checksum(data, n * sizeof(T));
      Handle              scalar(H5Screate(H5S_SCALAR), H5Sclose, what);
      Handle              attribute(
        H5Acreate2(
          set, "fnv1a64", H5T_NATIVE_UINT64, scalar, H5P_DEFAULT, H5P_DEFAULT),
        H5Aclose,
        what);
      check(H5Awrite(attribute, H5T_NATIVE_UINT64, &sum), what);
    }

    template <typename T>
    std::vector<T>
    read_array(const hid_t        group,
               const std::string &name,
               const hid_t        type,
               const std::string &path)
    {
      const std::string what = "dataset '" + name + "' of '" + path + "'";
      Handle            set(H5Dopen2(group, name.c_str(), H5P_DEFAULT),
                 H5Dclose,
                 "cannot open " + what);
      Handle space(H5Dget_space(set), H5Sclose, "cannot read " + what);
      if (H5Sget_simple_extent_ndims(space) != 1)
        throw std::runtime_error(what + " is not an array");
      hsize_t dims[1];
      H5Sget_simple_extent_dims(space, dims, nullptr);
      std::vector<T> values(dims[0]);
      if (dims[0] > 0)
        check(H5Dread(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()),
              "cannot read " + what);
      std::uint64_t stored = 0;
      Handle        attribute(H5Aopen(set, "fnv1a64", H5P_DEFAULT),
                       H5Aclose,
                       what + " has no checksum");
      check(H5Aread(attribute, H5T_NATIVE_UINT64, &stored),
            "cannot read the checksum of " + what);
      if (stored != checksum(values.data(), values.size() * sizeof(T)))
        throw std::runtime_error(what + " is damaged (checksum mismatch)");
      return values;
    }

    std::vector<std::string>
    member_names(const hid_t group, const std::string &path)
    {
      H5G_info_t info;
      check(H5Gget_info(group, &info), "cannot list '" + path + "'");
      std::vector<std::string> names;
      for (hsize_t i = 0; i < info.nlinks; ++i)
        {
          const ssize_t size = H5Lget_name_by_idx(
            group, ".", H5_INDEX_NAME, H5_ITER_INC, i, nullptr, 0, H5P_DEFAULT);
          check(size, "cannot list '" + path + "'");
          std::string name(size + 1, '\0');
          H5Lget_name_by_idx(group,
                             ".",
                             H5_INDEX_NAME,
                             H5_ITER_INC,
                             i,
                             name.data(),
                             size + 1,
                             H5P_DEFAULT);
          name.resize(size);
          names.push_back(name);
        }
      return names;
    }

    template <typename Map, typename F>
    void
    write_group(const hid_t        file,
                const char        *group_name,
                const Map         &map,
                const std::string &path,
                F                  write_one)
    {
      Handle group(
        H5Gcreate2(file, group_name, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
        H5Gclose,
        "cannot write '" + path + "'");
      for (const auto &[name, values] : map)
        write_one(group, name, values);
    }

    template <typename F>
    void
    read_group(const hid_t        file,
               const char        *group_name,
               const std::string &path,
               F                  read_one)
    {
      Handle group(H5Gopen2(file, group_name, H5P_DEFAULT),
                   H5Gclose,
                   "'" + path + "' is not an amfrac checkpoint (no group "
                     + group_name + ")");
      for (const auto &name : member_names(group, path))
        read_one(group, name);
    }
  } // namespace



  const std::vector<double> &
  CheckpointData::get(const std::string &name) const
  {
    const auto entry = reals.find(name);
    if (entry == reals.end())
      throw std::runtime_error("the checkpoint has no entry '" + name + "'");
    return entry->second;
  }



  double
  CheckpointData::get_scalar(const std::string &name) const
  {
    const auto &values = get(name);
    if (values.size() != 1)
      throw std::runtime_error("checkpoint entry '" + name
                               + "' is not a scalar");
    return values[0];
  }



  const std::vector<std::int64_t> &
  CheckpointData::get_integers(const std::string &name) const
  {
    const auto entry = integers.find(name);
    if (entry == integers.end())
      throw std::runtime_error("the checkpoint has no entry '" + name + "'");
    return entry->second;
  }



  std::int64_t
  CheckpointData::get_integer(const std::string &name) const
  {
    const auto &values = get_integers(name);
    if (values.size() != 1)
      throw std::runtime_error("checkpoint entry '" + name
                               + "' is not a scalar");
    return values[0];
  }



  const std::string &
  CheckpointData::get_text(const std::string &name) const
  {
    const auto entry = texts.find(name);
    if (entry == texts.end())
      throw std::runtime_error("the checkpoint has no entry '" + name + "'");
    return entry->second;
  }



  std::size_t
  CheckpointData::payload_bytes() const
  {
    std::size_t bytes = 0;
    for (const auto &entry : reals)
      bytes += entry.second.size() * sizeof(double);
    for (const auto &entry : integers)
      bytes += entry.second.size() * sizeof(std::int64_t);
    for (const auto &entry : texts)
      bytes += entry.second.size();
    return bytes;
  }



  void
  CheckpointData::write(const std::string &path) const
  {
    // Errors are reported by the return codes, not printed by HDF5.
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    Handle file(
      H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT),
      H5Fclose,
      "cannot create '" + path
        + "' (does the folder exist and is it writable?)");
    write_group(file, "real", reals, path, [&](hid_t g, auto &n, auto &v) {
      write_array(g, n, H5T_NATIVE_DOUBLE, v.data(), v.size(), path);
    });
    write_group(
      file, "integer", integers, path, [&](hid_t g, auto &n, auto &v) {
        write_array(g, n, H5T_NATIVE_INT64, v.data(), v.size(), path);
      });
    auto with_header      = texts;
    with_header["format"] = format_name;
    write_group(
      file, "text", with_header, path, [&](hid_t g, auto &n, auto &v) {
        write_array(g, n, H5T_NATIVE_CHAR, v.data(), v.size(), path);
      });
    const std::vector<std::int64_t> version = {format_version};
    write_array(
      file, "version", H5T_NATIVE_INT64, version.data(), version.size(), path);
    check(H5Fflush(file, H5F_SCOPE_GLOBAL), "cannot flush '" + path + "'");
    file.close_or_throw("cannot close '" + path
                        + "' (is the disk full or the folder gone?)");
  }



  CheckpointData
  CheckpointData::read(const std::string &path)
  {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    Handle         file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT),
                H5Fclose,
                "cannot open '" + path + "' as an HDF5 file");
    CheckpointData data;
    read_group(file, "text", path, [&](hid_t g, const std::string &name) {
      const auto chars = read_array<char>(g, name, H5T_NATIVE_CHAR, path);
      data.texts[name] = std::string(chars.begin(), chars.end());
    });
    if (data.texts["format"] != format_name)
      throw std::runtime_error("'" + path + "' is not an amfrac checkpoint");
    data.texts.erase("format");
    const auto version
      = read_array<std::int64_t>(file, "version", H5T_NATIVE_INT64, path);
    if (version.size() != 1 || version[0] != format_version)
      throw std::runtime_error(
        "'" + path + "' has checkpoint format version "
        + (version.empty() ? std::string("?") : std::to_string(version[0]))
        + "; this amfrac reads version " + std::to_string(format_version));
    read_group(file, "real", path, [&](hid_t g, const std::string &name) {
      data.reals[name] = read_array<double>(g, name, H5T_NATIVE_DOUBLE, path);
    });
    read_group(file, "integer", path, [&](hid_t g, const std::string &name) {
      data.integers[name]
        = read_array<std::int64_t>(g, name, H5T_NATIVE_INT64, path);
    });
    return data;
  }
} // namespace amfrac
