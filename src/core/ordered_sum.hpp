// A sum of many terms in parallel that comes out the same whatever the
// number of threads: the terms are summed in chunks of a fixed size, and
// the chunks' sums added in order. (A reduction clause would add the
// threads' partial sums in an order that depends on how many there are,
// and a mesh's figures would change with the machine.)
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

namespace lbmshape {

// term(0) + term(1) + ... + term(count - 1), for a Sum that starts at
// Sum{} and adds with +=.
template <class Sum, class Term>
Sum orderedSum(size_t count, Term term)
{
  constexpr size_t chunk = 16384;
  const size_t chunks = (count + chunk - 1) / chunk;
  std::vector<Sum> sums(chunks, Sum{});
#pragma omp parallel for schedule(static)
  for (size_t k = 0; k < chunks; ++k)
    for (size_t i = k * chunk; i < std::min(count, (k + 1) * chunk); ++i) sums[k] += term(i);
  Sum total{};
  for (const Sum& s : sums) total += s;
  return total;
}

}  // namespace lbmshape
