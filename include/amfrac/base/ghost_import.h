#pragma once

#include <Epetra_Import.h>
#include <deal.II/lac/trilinos_vector.h>
#include <memory>

namespace amfrac
{
  /**
   * ghosted = owned for Trilinos vectors, with the Epetra_Import kept from
   * one call to the next. deal.II's assignment builds a new import every
   * time (a pass over both maps with hash look-ups), which in an explicit
   * run's per-step crack check cost as much as the check itself. A new map
   * on either side (a new numbering) builds a new one; the import holds
   * copies of both maps, so a new map cannot take an old one's address.
   */
  class GhostImport
  {
  public:
    using Vector = dealii::TrilinosWrappers::MPI::Vector;

    void
    operator()(const Vector &owned, Vector &ghosted)
    {
      const auto &target = ghosted.trilinos_vector().Map();
      const auto &source = owned.trilinos_vector().Map();
      if (!import || import->TargetMap().DataPtr() != target.DataPtr()
          || import->SourceMap().DataPtr() != source.DataPtr())
        import = std::make_unique<Epetra_Import>(target, source);
      const int error
        = ghosted.trilinos_vector().Import(owned.trilinos_vector(),
                                           *import,
                                           Insert);
      AssertThrow(error == 0, dealii::ExcMessage("GhostImport: Epetra error"));
    }

  private:
    std::unique_ptr<Epetra_Import> import;
  };
} // namespace amfrac
