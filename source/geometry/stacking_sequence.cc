#include <amfrac/geometry/stacking_sequence.h>
#include <cctype>
#include <stdexcept>

namespace amfrac
{
  namespace
  {
    /** A recursive-descent parser over the sequence string. */
    class StackingParser
    {
    public:
      explicit StackingParser(const std::string &text)
        : text(text)
      {}

      std::vector<Ply>
      parse()
      {
        skip_spaces();
        expect('[');
        std::vector<Ply> plies = parse_list();
        expect(']');
        const unsigned int repeats = parse_optional_repeat(true);
        std::vector<Ply>   result;
        for (unsigned int r = 0; r < repeats; ++r)
          result.insert(result.end(), plies.begin(), plies.end());
        skip_spaces();
        if (position < text.size() && (peek() == 's' || peek() == 'S'))
          {
            ++position;
            // Mirror from a copy: inserting a vector's own range is UB.
            const std::vector<Ply> mirrored(result.rbegin(), result.rend());
            result.insert(result.end(), mirrored.begin(), mirrored.end());
          }
        if (result.size() > max_plies)
          fail("more than " + std::to_string(max_plies) + " plies");
        skip_spaces();
        if (position != text.size())
          fail("unexpected text after the closing bracket");
        return result;
      }

    private:
      const std::string &text;
      std::size_t        position = 0;
      /** A laminate of more plies is a typo, not a laminate. */
      static constexpr std::size_t max_plies = 10000;

      [[noreturn]] void
      fail(const std::string &what) const
      {
        throw std::invalid_argument(
          "malformed stacking sequence '" + text + "' at character "
          + std::to_string(position + 1) + ": " + what);
      }

      char
      peek() const
      {
        return position < text.size() ? text[position] : '\0';
      }

      void
      skip_spaces()
      {
        while (position < text.size()
               && std::isspace(static_cast<unsigned char>(text[position])))
          ++position;
      }

      void
      expect(const char c)
      {
        skip_spaces();
        if (peek() != c)
          fail(std::string("expected '") + c + "'");
        ++position;
      }

      bool
      accept(const std::string &token)
      {
        if (text.compare(position, token.size(), token) == 0)
          {
            position += token.size();
            return true;
          }
        return false;
      }

      std::vector<Ply>
      parse_list()
      {
        std::vector<Ply> plies = parse_item();
        skip_spaces();
        while (peek() == '/')
          {
            ++position;
            const std::vector<Ply> more = parse_item();
            plies.insert(plies.end(), more.begin(), more.end());
            skip_spaces();
          }
        return plies;
      }

      std::vector<Ply>
      parse_item()
      {
        skip_spaces();
        std::vector<Ply> unit;
        bool             group = false;
        if (peek() == '(')
          {
            ++position;
            unit = parse_list();
            expect(')');
            group = true;
          }
        else
          unit = parse_ply_or_pair();
        const unsigned int repeats = parse_optional_repeat(group);
        if (unit.size() * repeats > max_plies)
          fail("more than " + std::to_string(max_plies) + " plies");
        std::vector<Ply> result;
        for (unsigned int r = 0; r < repeats; ++r)
          result.insert(result.end(), unit.begin(), unit.end());
        return result;
      }

      /** '_n', or a bare n if @p bare_allowed (right after ']' or ')');
       * default 1. */
      unsigned int
      parse_optional_repeat(const bool bare_allowed)
      {
        skip_spaces();
        const bool underscore = (peek() == '_');
        if (underscore)
          ++position;
        if (!std::isdigit(static_cast<unsigned char>(peek())))
          {
            if (underscore)
              fail("expected a repeat count after '_'");
            return 1;
          }
        if (!underscore && !bare_allowed)
          fail("expected '/' between plies");
        std::size_t count = 0;
        while (std::isdigit(static_cast<unsigned char>(peek())))
          {
            count = 10 * count + (peek() - '0');
            if (count > max_plies)
              fail("repeat count larger than " + std::to_string(max_plies));
            ++position;
          }
        if (count == 0)
          fail("a repeat count must be at least 1");
        return static_cast<unsigned int>(count);
      }

      std::vector<Ply>
      parse_ply_or_pair()
      {
        // A sign pair (±, +-, -+) makes two plies of opposite angles.
        int pair_sign = 0;
        if (accept("\u00b1") || accept("+-"))
          pair_sign = +1;
        else if (accept("\u2213") || accept("-+"))
          pair_sign = -1;
        const double      angle    = parse_angle(pair_sign != 0);
        const std::string material = parse_optional_material();
        if (pair_sign == 0)
          return {Ply{angle, material}};
        return {Ply{pair_sign * angle, material},
                Ply{-pair_sign * angle, material}};
      }

      double
      parse_angle(const bool unsigned_only)
      {
        skip_spaces();
        const std::size_t start = position;
        if (!unsigned_only && (peek() == '+' || peek() == '-'))
          ++position;
        bool         digits = false;
        unsigned int dots   = 0;
        while (std::isdigit(static_cast<unsigned char>(peek()))
               || peek() == '.')
          {
            digits = digits || (peek() != '.');
            dots += (peek() == '.');
            ++position;
          }
        if (!digits || dots > 1 || position - start > 24)
          {
            position = start;
            fail("expected a ply angle in degrees");
          }
        const double angle = std::stod(text.substr(start, position - start));
        if (angle < -360. || angle > 360.)
          {
            position = start;
            fail("a ply angle must lie in [-360, 360] degrees");
          }
        return angle;
      }

      std::string
      parse_optional_material()
      {
        if (peek() != '@')
          return "";
        ++position;
        const std::size_t start = position;
        while (std::isalnum(static_cast<unsigned char>(peek())) || peek() == '-'
               || peek() == '.')
          ++position;
        if (position == start)
          fail("expected a material name after '@'");
        return text.substr(start, position - start);
      }
    };
  } // namespace



  std::vector<Ply>
  parse_stacking_sequence(const std::string &sequence)
  {
    return StackingParser(sequence).parse();
  }
} // namespace amfrac
