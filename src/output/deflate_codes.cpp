#include "output/deflate_codes.hpp"

#include <algorithm>
#include <utility>
#include <vector>

namespace sl::detail {

void huffmanLengths(const std::uint32_t* counts, int symbols, int limit, std::uint8_t* lengths) {
  std::vector<std::uint64_t> weight(counts, counts + symbols);
  std::fill(lengths, lengths + symbols, 0);
  while (true) {
    std::vector<std::pair<std::uint64_t, int>> leaves;
    for (int s = 0; s < symbols; ++s)
      if (weight[s] > 0) leaves.emplace_back(weight[s], s);
    if (leaves.empty()) return;
    if (leaves.size() == 1) {
      const int s = leaves[0].second;
      lengths[s] = 1;
      lengths[s == 0 ? 1 : 0] = 1;
      return;
    }
    std::sort(leaves.begin(), leaves.end());
    // Two queues (sorted leaves, then internal nodes in order of creation): parents have higher indices.
    const std::size_t m = leaves.size(), nodes = 2 * m - 1;
    std::vector<std::uint64_t> w(nodes);
    std::vector<std::size_t> parent(nodes, 0);
    for (std::size_t i = 0; i < m; ++i) w[i] = leaves[i].first;
    std::size_t leaf = 0, inner = m, next = m;
    auto pick = [&] { return (leaf < m && (inner >= next || w[leaf] <= w[inner])) ? leaf++ : inner++; };
    while (next < nodes) {
      const std::size_t a = pick(), b = pick();
      w[next] = w[a] + w[b];
      parent[a] = parent[b] = next++;
    }
    std::vector<int> depth(nodes, 0);
    for (std::size_t i = nodes - 1; i-- > 0;) depth[i] = depth[parent[i]] + 1;
    if (*std::max_element(depth.begin(), depth.begin() + static_cast<std::ptrdiff_t>(m)) <= limit) {
      for (std::size_t i = 0; i < m; ++i) lengths[leaves[i].second] = static_cast<std::uint8_t>(depth[i]);
      return;
    }
    for (auto& x : weight) x = (x + 1) / 2;
  }
}

void canonicalCodes(const std::uint8_t* lengths, int symbols, std::uint32_t* codes) {
  int count[16] = {};
  for (int s = 0; s < symbols; ++s) ++count[lengths[s]];
  count[0] = 0;
  std::uint32_t next[16] = {};
  std::uint32_t code = 0;
  for (int bits = 1; bits < 16; ++bits) {
    code = (code + static_cast<std::uint32_t>(count[bits - 1])) << 1;
    next[bits] = code;
  }
  for (int s = 0; s < symbols; ++s) {
    const int length = lengths[s];
    codes[s] = 0;
    if (length == 0) continue;
    std::uint32_t c = next[length]++, reversed = 0;
    for (int b = 0; b < length; ++b, c >>= 1) reversed = (reversed << 1) | (c & 1);
    codes[s] = reversed;
  }
}

}  // namespace sl::detail
