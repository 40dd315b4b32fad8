// STREAM-type triad a = b + s c on arrays far larger than the caches: the
// memory bandwidth the explicit kernels are compared with. Counts 24 bytes
// per element (two loads, one store; write-allocate traffic not counted,
// as in STREAM). usage: stream_triad [MiB per array]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

int
main(int argc, char **argv)
{
  const std::size_t   n = (argc > 1 ? std::atol(argv[1]) : 256) * 131072;
  std::vector<double> a(n, 0), b(n, 1), c(n, 2);
  std::vector<double> seconds;
  for (int repeat = 0; repeat < 10; ++repeat)
    {
      const auto start = std::chrono::steady_clock::now();
      for (std::size_t i = 0; i < n; ++i)
        a[i] = b[i] + 3. * c[i];
      seconds.push_back(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count());
    }
  std::sort(seconds.begin(), seconds.end());
  std::printf("triad: %.2f GB/s (best of 10), %.2f GB/s (median); check %g\n",
              24. * n / seconds[0] * 1e-9,
              24. * n / seconds[5] * 1e-9,
              a[n / 2]);
  return 0;
}
