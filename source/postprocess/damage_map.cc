#include <algorithm>
#include <amfrac/postprocess/atomic_file.h>
#include <amfrac/postprocess/damage_map.h>
#include <array>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <limits>
#include <map>
#include <zlib.h>

namespace amfrac
{
  namespace
  {
    void
    put_u32(std::string &s, const std::uint32_t v)
    {
      for (int shift = 24; shift >= 0; shift -= 8)
        s.push_back(static_cast<char>((v >> shift) & 0xff));
    }

    /** length, type, data, CRC of type and data */
    void
    put_chunk(std::ostream &out, const char *type, const std::string &data)
    {
      std::string chunk;
      put_u32(chunk, data.size());
      chunk += type;
      chunk += data;
      uLong crc = crc32(0L, Z_NULL, 0);
      crc       = crc32(crc,
                  reinterpret_cast<const Bytef *>(chunk.data() + 4),
                  chunk.size() - 4);
      put_u32(chunk, crc);
      out.write(chunk.data(), chunk.size());
    }

    struct MapPoint
    {
      double       x, y, damage;
      unsigned int status;
    };

    using Color = std::array<unsigned char, 3>;

    Color
    color_of(const MapPoint &p)
    {
      if (p.status == 2)
        return {{0, 0, 0}};
      if (p.status == 3)
        return {{30, 60, 200}};
      if (p.damage <= 0)
        return {{255, 255, 255}};
      const double d = std::min(1., p.damage);
      return {{static_cast<unsigned char>(255 - 55 * d),
               static_cast<unsigned char>(220 * (1 - d)),
               0}};
    }

    /** Rank the severity of a point, to break ties between the two faces
     * or the neighbouring cells that share a location. */
    double
    severity(const MapPoint &p)
    {
      return p.status >= 2 ? 2 + p.status : p.damage;
    }

    /** Top view of one interface, @p pixels across its longer side. */
    std::vector<unsigned char>
    rasterize(const std::vector<MapPoint> &points,
              const unsigned int           pixels,
              unsigned int                &width,
              unsigned int                &height)
    {
      double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
      for (const auto &p : points)
        x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y),
        y1 = std::max(y1, p.y);
      const double extent = std::max({x1 - x0, y1 - y0, 1e-300});
      const double scale  = pixels / extent;
      width  = std::max(1u, unsigned(std::lround((x1 - x0) * scale)));
      height = std::max(1u, unsigned(std::lround((y1 - y0) * scale)));
      // Buckets of about one point each for the nearest-point search.
      const unsigned int n = std::max(1., std::sqrt(1. * points.size()));
      const double bx = (x1 - x0) / n + 1e-300, by = (y1 - y0) / n + 1e-300;
      std::vector<std::vector<unsigned int>> buckets(n * n);
      auto bucket = [&](const double x, const double y) {
        const int i = std::clamp(int((x - x0) / bx), 0, int(n) - 1);
        const int j = std::clamp(int((y - y0) / by), 0, int(n) - 1);
        return std::make_pair(i, j);
      };
      for (unsigned int k = 0; k < points.size(); ++k)
        {
          const auto [i, j] = bucket(points[k].x, points[k].y);
          buckets[j * n + i].push_back(k);
        }
      std::vector<unsigned char> rgb(3 * width * height, 200);
      const double               tie = 1e-9 * extent * extent;
      for (unsigned int row = 0; row < height; ++row)
        for (unsigned int col = 0; col < width; ++col)
          {
            const double x      = x0 + (col + 0.5) / width * (x1 - x0);
            const double y      = y1 - (row + 0.5) / height * (y1 - y0);
            const auto [bi, bj] = bucket(x, y);
            double best         = std::numeric_limits<double>::max();
            int    found        = -1;
            for (int j = std::max(0, bj - 1); j <= std::min(int(n) - 1, bj + 1);
                 ++j)
              for (int i = std::max(0, bi - 1);
                   i <= std::min(int(n) - 1, bi + 1);
                   ++i)
                for (const unsigned int k : buckets[j * n + i])
                  {
                    const double d2 = (points[k].x - x) * (points[k].x - x)
                                      + (points[k].y - y) * (points[k].y - y);
                    if (d2 < best - tie
                        || (d2 < best + tie && found >= 0
                            && severity(points[k]) > severity(points[found])))
                      best = std::min(best, d2), found = k;
                  }
            if (found >= 0)
              {
                const Color c = color_of(points[found]);
                std::copy(c.begin(), c.end(), &rgb[3 * (row * width + col)]);
              }
          }
      return rgb;
    }
  } // namespace



  void
  write_png(const std::string                &path,
            const unsigned int                width,
            const unsigned int                height,
            const std::vector<unsigned char> &rgb)
  {
    // Each row starts with its filter type (0: none).
    std::string raw;
    raw.reserve((3 * width + 1) * height);
    for (unsigned int row = 0; row < height; ++row)
      {
        raw.push_back(0);
        raw.append(reinterpret_cast<const char *>(&rgb[3 * width * row]),
                   3 * width);
      }
    uLongf      size = compressBound(raw.size());
    std::string compressed(size, '\0');
    if (compress2(reinterpret_cast<Bytef *>(compressed.data()),
                  &size,
                  reinterpret_cast<const Bytef *>(raw.data()),
                  raw.size(),
                  6)
        != Z_OK)
      throw std::runtime_error("cannot compress the image '" + path + "'");
    compressed.resize(size);
    std::string header;
    put_u32(header, width);
    put_u32(header, height);
    header += std::string("\x08\x02\x00\x00\x00", 5); // 8-bit RGB
    write_atomically(path, [&](std::ostream &out) {
      out.write("\x89PNG\r\n\x1a\n", 8);
      put_chunk(out, "IHDR", header);
      put_chunk(out, "IDAT", compressed);
      put_chunk(out, "IEND", "");
    });
  }



  template <int dim>
  std::vector<std::string>
  write_damage_maps(const std::string                            &directory,
                    const unsigned int                            step,
                    const std::vector<InterfacePointRecord<dim>> &points,
                    const MPI_Comm                                comm)
  {
    if (dim != 3)
      return {};
    std::vector<double> local;
    // Top views are of ply interfaces; inserted cracks cut across plies.
    for (const auto &p : points)
      if (p.interface != InterfacePointRecord<dim>::crack)
        local.insert(local.end(),
                     {p.position[0],
                      p.position[1],
                      double(p.interface),
                      p.damage,
                      double(p.status)});
    const auto gathered = Utilities::MPI::gather(comm, local, 0);
    if (Utilities::MPI::this_mpi_process(comm) != 0)
      return {};
    std::map<unsigned int, std::vector<MapPoint>> by_interface;
    for (const auto &part : gathered)
      for (std::size_t i = 0; i + 4 < part.size(); i += 5)
        by_interface[unsigned(part[i + 2])].push_back(
          {part[i], part[i + 1], part[i + 3], unsigned(part[i + 4])});
    std::vector<std::string> written;
    for (const auto &[k, map_points] : by_interface)
      {
        unsigned int width, height;
        const auto   rgb  = rasterize(map_points, 400, width, height);
        const auto   path = directory + "/damage-interface-" + std::to_string(k)
                          + "-" + Utilities::int_to_string(step, 5) + ".png";
        write_png(path, width, height, rgb);
        written.push_back(path);
      }
    return written;
  }



  template std::vector<std::string>
  write_damage_maps<2>(const std::string &,
                       const unsigned int,
                       const std::vector<InterfacePointRecord<2>> &,
                       const MPI_Comm);
  template std::vector<std::string>
  write_damage_maps<3>(const std::string &,
                       const unsigned int,
                       const std::vector<InterfacePointRecord<3>> &,
                       const MPI_Comm);
} // namespace amfrac
