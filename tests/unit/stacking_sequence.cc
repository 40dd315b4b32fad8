// Stacking-sequence parser: valid forms give the expected ply lists,
// malformed ones throw with the position of the error.
#include "../check.h"

#include <amfrac/geometry/stacking_sequence.h>
#include <stdexcept>

using namespace amfrac;

namespace
{
  std::vector<double>
  angles(const std::string &text)
  {
    std::vector<double> result;
    for (const Ply &p : parse_stacking_sequence(text))
      result.push_back(p.angle);
    return result;
  }

  bool
  rejects(const std::string &text)
  {
    try
      {
        parse_stacking_sequence(text);
      }
    catch (const std::invalid_argument &e)
      {
        return std::string(e.what()).find("at character") != std::string::npos;
      }
    return false;
  }
} // namespace

int
main()
{
  using V = std::vector<double>;
  CHECK(angles("[0/90/45/-45]s") == V({0, 90, 45, -45, -45, 45, 90, 0}));
  CHECK(angles("[0_4/0_16]").size() == 20);
  CHECK(angles("[(0/90)_2]s") == V({0, 90, 0, 90, 90, 0, 90, 0}));
  CHECK(angles("[\u00b145]") == V({45, -45}));
  CHECK(angles("[+-45/0]") == V({45, -45, 0}));
  CHECK(angles("[-+30]") == V({-30, 30}));
  CHECK(angles("[0/90]_2s") == V({0, 90, 0, 90, 90, 0, 90, 0}));
  CHECK(angles("[ 0 / 22.5 ]") == V({0, 22.5}));
  CHECK(angles("[\u00b145_2]") == V({45, -45, 45, -45}));
  CHECK(angles("[((0/90)_2/45)_2]").size() == 10);
  CHECK(angles("[0/90]2s") == V({0, 90, 0, 90, 90, 0, 90, 0}));
  const auto named = parse_stacking_sequence("[0@glass/90]");
  CHECK(named[0].material == "glass" && named[1].material.empty());
  // Mirroring keeps the materials of the mirrored plies.
  const auto hybrid = parse_stacking_sequence("[0@glass/90/45@aramid]s");
  CHECK(hybrid.size() == 6 && hybrid[3].material == "aramid"
        && hybrid[4].material.empty() && hybrid[5].material == "glass");

  for (const char *bad : {"",
                          "0/90",
                          "[0/90",
                          "[0//90]",
                          "[0_0]",
                          "[0_]",
                          "[(0/90]",
                          "[0/90]x",
                          "[abc]",
                          "[0@]",
                          "[400]",
                          "[0/90]s s",
                          "[0 90]",
                          "[0/90 45]",
                          "[1.2.3]",
                          "[0_99999999999]",
                          "[(0/90)_6000]",
                          "[0_100/90]_100"})
    {
      const bool ok = rejects(bad);
      CHECK(ok);
      if (!ok)
        std::cerr << "  accepted: '" << bad << "'" << std::endl;
    }
  return amfrac_test::summary();
}
