#pragma once

namespace amfrac
{
  /** True if @p face is @p parent or one of its descendants (refined
   * faces, any refinement case): how a crack face or a strength value
   * follows a face through refinement. */
  template <typename FaceIterator>
  bool
  face_within(const FaceIterator &face, const FaceIterator &parent)
  {
    if (face == parent)
      return true;
    if (!parent->has_children())
      return false;
    for (unsigned int c = 0; c < parent->n_children(); ++c)
      if (face_within(face, parent->child(c)))
        return true;
    return false;
  }
} // namespace amfrac
