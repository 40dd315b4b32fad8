// checkpoint_diff DIR_A DIR_B RTOL [ATOL]: compare the newest checkpoints in
// two folders entry by entry (the run file and every rank's part): integers and
// texts exactly (except the stored parameters: the two runs differ in
// their output folders; the number of ranks; and the count of
// factorizations, a cost: a resumed run cannot reuse the factorization of
// the run before it; the rank parts are merged by cell and interface
// face first, so that runs on different numbers of ranks compare), reals to
// relative RTOL per entry (with a floor of RTOL * 1e-6 times the largest
// magnitude of the entry, for round-off around zero; fields normwise). Prints
// the worst entry; exit status 1 on any difference.
#include <algorithm>
#include <amfrac/checkpoint/checkpoint_store.h>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <map>
#include <mpi.h>
#include <sstream>
#include <string>

namespace
{
  using amfrac::CheckpointData;

  /** Differences up to this are accepted everywhere (0 unless given). */
  double absolute_tolerance = 0;

  struct Worst
  {
    double      ratio = 0;
    std::string where;
  };

  bool
  compare_reals(const std::vector<double> &a,
                const std::vector<double> &b,
                const double               rtol,
                const std::string         &where,
                Worst                     &worst,
                const double               floor = 1e-6)
  {
    if (a.size() != b.size())
      {
        std::cerr << where << ": sizes " << a.size() << " and " << b.size()
                  << std::endl;
        return false;
      }
    double scale = 0;
    for (const double x : a)
      scale = std::max(scale, std::abs(x));
    bool same = true;
    for (std::size_t i = 0; i < a.size(); ++i)
      {
        const double allowed
          = rtol * std::max({std::abs(a[i]), std::abs(b[i]), floor * scale})
            + absolute_tolerance;
        // NaN stands for "not yet known" (a remeshing's reached error):
        // the same in both, or a difference.
        if (std::isnan(a[i]) && std::isnan(b[i]))
          continue;
        const double difference = std::abs(a[i] - b[i]);
        const double ratio      = allowed > 0    ? difference / allowed :
                                  difference > 0 ? INFINITY :
                                                   0;
        if (ratio > worst.ratio)
          worst = {ratio, where + "[" + std::to_string(i) + "]"};
        same = same && ratio <= 1;
      }
    return same;
  }

  /** A table (history.csv, adaptivity.csv): NAME.values with
   * NAME.columns. */
  bool
  is_table(const CheckpointData &data, const std::string &name)
  {
    const std::string suffix = ".values";
    return name.size() > suffix.size()
           && name.compare(name.size() - suffix.size(), suffix.size(), suffix)
                == 0
           && data.has(name.substr(0, name.size() - suffix.size())
                       + ".columns");
  }

  /** Column by column: the floor of a column (energy balance error,
   * round-off around zero) is its own largest magnitude. */
  bool
  compare_table(const CheckpointData &a,
                const CheckpointData &b,
                const std::string    &name,
                const double          rtol,
                const std::string    &where,
                Worst                &worst)
  {
    const std::string columns = a.get_text(
      name.substr(0, name.size() - std::string(".values").size()) + ".columns");
    const std::size_t n = std::count(columns.begin(), columns.end(), '\n');
    const auto       &x = a.get(name), &y = b.get(name);
    if (n == 0 || x.size() != y.size())
      return compare_reals(x, y, rtol, where, worst);
    std::vector<std::string> names;
    std::istringstream       lines(columns);
    for (std::string line; std::getline(lines, line);)
      names.push_back(line);
    bool same = true;
    for (std::size_t c = 0; c < n; ++c)
      {
        // Wall times (a remeshing's Gmsh and transfer seconds) are no
        // state.
        const std::string suffix = "_seconds";
        if (c < names.size() && names[c].size() > suffix.size()
            && names[c].compare(names[c].size() - suffix.size(),
                                suffix.size(),
                                suffix)
                 == 0)
          continue;
        std::vector<double> column_x, column_y;
        for (std::size_t i = c; i < x.size(); i += n)
          {
            column_x.push_back(x[i]);
            column_y.push_back(y[i]);
          }
        same = compare_reals(column_x,
                             column_y,
                             rtol,
                             where + " column " + std::to_string(c),
                             worst)
               && same;
      }
    return same;
  }

  bool
  compare(const CheckpointData           &a,
          const CheckpointData           &b,
          const std::vector<std::string> &names,
          const double                    rtol,
          const std::string              &file,
          Worst                          &worst)
  {
    bool same = true;
    for (const auto &name : names)
      {
        const std::string where = file + ":" + name;
        if (a.has(name) != b.has(name))
          {
            std::cerr << where << ": in one checkpoint only" << std::endl;
            same = false;
          }
        else if (!a.has(name) || name == "ranks"
                 || name == "newton.factorizations" || name == "parameters")
          continue;
        else if (a.is_real(name) && is_table(a, name))
          same = compare_table(a, b, name, rtol, where, worst) && same;
        else if (a.is_real(name))
          same = compare_reals(a.get(name), b.get(name), rtol, where, worst)
                 && same;
        else if (a.is_integer(name)
                 && a.get_integers(name) != b.get_integers(name))
          {
            std::cerr << where << ": integers differ" << std::endl;
            same = false;
          }
        else if (a.is_text(name) && a.get_text(name) != b.get_text(name))
          {
            std::cerr << where << ": texts differ" << std::endl;
            same = false;
          }
      }
    return same;
  }
  /** Per entry name, per key (a cell, or a cell and a face), the
   * values; and the summed counters. */
  struct Merged
  {
    std::map<std::string,
             std::map<std::vector<std::int64_t>, std::vector<double>>>
                              slices;
    std::vector<std::int64_t> counters;
  };

  void
  add_slices(Merged                          &merged,
             const std::string               &name,
             const std::vector<std::int64_t> &keys,
             const unsigned int               key_size,
             const std::vector<std::int64_t> &counts,
             const std::vector<double>       &values)
  {
    std::size_t total = 0;
    for (const auto n : counts)
      total += n;
    if (total == 0)
      return;
    const std::size_t per_count = values.size() / total;
    std::size_t       offset    = 0;
    for (std::size_t e = 0; e < counts.size(); ++e)
      {
        const std::vector<std::int64_t> key(keys.begin() + key_size * e,
                                            keys.begin() + key_size * (e + 1));
        const std::size_t               n = counts[e] * per_count;
        merged.slices[name][key].assign(values.begin() + offset,
                                        values.begin() + offset + n);
        offset += n;
      }
  }

  Merged
  merge(const std::vector<CheckpointData> &parts)
  {
    Merged merged;
    for (const auto &part : parts)
      {
        const auto                     &cells = part.get_integers("cells");
        const std::vector<std::int64_t> ones(cells.size() / 4, 1);
        for (const auto &name : part.names())
          if (name.rfind("vector.", 0) == 0)
            add_slices(merged, name, cells, 4, ones, part.get(name));
        if (!part.has("interfaces.keys"))
          continue;
        const auto               &keys = part.get_integers("interfaces.keys");
        std::vector<std::int64_t> points;
        for (std::size_t i = 5; i < keys.size(); i += 6)
          points.push_back(keys[i]);
        add_slices(merged,
                   "interfaces.states",
                   keys,
                   6,
                   points,
                   part.get("interfaces.states"));
        const auto &counters = part.get_integers("interfaces.counters");
        merged.counters.resize(counters.size());
        for (std::size_t i = 0; i < counters.size(); ++i)
          merged.counters[i] += counters[i];
      }
    return merged;
  }

  bool
  compare_merged(const Merged &a,
                 const Merged &b,
                 const double  rtol,
                 Worst        &worst)
  {
    bool same = a.counters == b.counters;
    if (!same)
      std::cerr << "interface contact counters differ" << std::endl;
    for (const auto &[name, slices] : a.slices)
      {
        const auto other = b.slices.find(name);
        if (other == b.slices.end() || other->second.size() != slices.size())
          {
            std::cerr << name << ": different cells or faces" << std::endl;
            same = false;
            continue;
          }
        std::vector<double> values_a, values_b;
        for (const auto &[key, values] : slices)
          {
            const auto match = other->second.find(key);
            if (match == other->second.end())
              {
                std::cerr << name << ": different cells or faces" << std::endl;
                same = false;
                break;
              }
            values_a.insert(values_a.end(), values.begin(), values.end());
            values_b.insert(values_b.end(),
                            match->second.begin(),
                            match->second.end());
          }
        // A field normwise: its entries near zero (a residual off the
        // supports) are round-off of its largest.
        same = compare_reals(values_a, values_b, rtol, name, worst, 1.) && same;
      }
    return same;
  }
} // namespace

int
main(int argc, char *argv[])
{
  MPI_Init(&argc, &argv);
  if (argc != 4 && argc != 5)
    {
      std::cerr << "usage: checkpoint_diff DIR_A DIR_B RTOL [ATOL]"
                << std::endl;
      return 2;
    }
  if (argc == 5)
    absolute_tolerance = std::atof(argv[4]);
  const double rtol   = std::atof(argv[3]);
  int          status = 0;
  try
    {
      const auto folder_a = amfrac::CheckpointStore::newest(argv[1]);
      const auto folder_b = amfrac::CheckpointStore::newest(argv[2]);
      if (folder_a.empty() || folder_b.empty())
        throw std::runtime_error("no checkpoint in one of the folders");
      const auto a = amfrac::CheckpointStore::read(folder_a, MPI_COMM_SELF);
      const auto b = amfrac::CheckpointStore::read(folder_b, MPI_COMM_SELF);
      std::cout << folder_a << " vs " << folder_b << std::endl;
      Worst worst;
      bool  same  = true;
      auto  names = a.run.names();
      for (const auto &n : b.run.names())
        names.push_back(n);
      same = compare(a.run, b.run, names, rtol, "run", worst) && same;
      // The parts by cell (fields) and by interface face (histories), so
      // that runs on different numbers of ranks compare.
      const auto merged_a = merge(a.parts), merged_b = merge(b.parts);
      same = compare_merged(merged_a, merged_b, rtol, worst) && same;
      std::cout << "largest difference: " << worst.ratio
                << " of the tolerance, at " << worst.where << std::endl;
      if (!same)
        {
          std::cout << "the checkpoints differ" << std::endl;
          status = 1;
        }
    }
  catch (const std::exception &e)
    {
      std::cerr << "checkpoint_diff: " << e.what() << std::endl;
      status = 1;
    }
  MPI_Finalize();
  return status;
}
