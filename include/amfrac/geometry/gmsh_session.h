#pragma once

#include <amfrac/parameters/input_error.h>
#include <functional>
#include <gmsh.h>
#include <string>
#include <vector>

namespace amfrac
{
  /** Gmsh is one global state: a session initializes it quietly and
   * single-threaded (the same mesh on every run) and finalizes it
   * whatever happens. */
  class GmshSession
  {
  public:
    GmshSession()
    {
      gmsh::initialize(0, nullptr, /*readConfigFiles=*/false);
      gmsh::option::setNumber("General.Terminal", 0);
      gmsh::option::setNumber("General.NumThreads", 1);
      gmsh::logger::start();
    }

    ~GmshSession()
    {
      gmsh::finalize();
    }

    GmshSession(const GmshSession &) = delete;
    GmshSession &
    operator=(const GmshSession &)
      = delete;

    /** Run @p steps on Gmsh's model: what Gmsh throws or logs becomes an
     * InputError for @p parameter naming @p file (Gmsh throws a bare
     * string or int, and logs the message). */
    static void
    run(const std::string           &parameter,
        const std::string           &file,
        const std::function<void()> &steps)
    {
      try
        {
          steps();
        }
      catch (const InputError &)
        {
          throw;
        }
      catch (...)
        {
          check(parameter, "on '" + file + "'");
          throw InputError(parameter, "Gmsh failed on '" + file + "'");
        }
    }

    /** Every physical group of dimension @p dim in the current model:
     * @p visit(name, entities). */
    static void
    for_each_physical_group(
      const int dim,
      const std::function<void(const std::string &, const std::vector<int> &)>
        &visit)
    {
      gmsh::vectorpair groups;
      gmsh::model::getPhysicalGroups(groups, dim);
      for (const auto &[group_dim, group] : groups)
        {
          std::string name;
          gmsh::model::getPhysicalName(group_dim, group, name);
          std::vector<int> entities;
          gmsh::model::getEntitiesForPhysicalGroup(group_dim, group, entities);
          visit(name, entities);
        }
    }

    /** Gmsh's name of its element type @p type, e.g. "Tetrahedron 4". */
    static std::string
    element_name(const int type)
    {
      std::string         name;
      int                 dim, order, n_nodes, n_primary;
      std::vector<double> local;
      gmsh::model::mesh::getElementProperties(
        type, name, dim, order, n_nodes, local, n_primary);
      return name;
    }

    /** Throw an InputError for @p parameter if Gmsh has logged an error
     * (it does not always throw). */
    static void
    check(const std::string &parameter, const std::string &what)
    {
      std::string error;
      gmsh::logger::getLastError(error);
      if (!error.empty())
        throw InputError(parameter, "Gmsh failed " + what + ": " + error);
    }
  };
} // namespace amfrac
