#include "snow/print_store_file.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cstring>
#include <fstream>
#include <istream>
#include <ostream>
#include <set>
#include <string>

namespace wg::snow {

namespace {

constexpr std::array<char, 8> kMagic{'W', 'G', 'P', 'R', 'I', 'N', 'T', 'S'};

template <typename T>
void put(std::ostream& out, T value) {
  auto bits = std::bit_cast<std::array<unsigned char, sizeof(T)>>(value);
  if constexpr (std::endian::native == std::endian::big) std::reverse(bits.begin(), bits.end());
  out.write(reinterpret_cast<const char*>(bits.data()), sizeof(T));
}

// Reads little-endian fields, counting bytes so every error says where it happened.
class FieldReader {
 public:
  explicit FieldReader(std::istream& in) : in_(in) {}

  template <typename T>
  T read(const char* field) {
    std::array<unsigned char, sizeof(T)> bits{};
    in_.read(reinterpret_cast<char*>(bits.data()), sizeof(T));
    if (in_.gcount() != std::streamsize(sizeof(T))) fail(std::string("truncated: the file ends inside ") + field);
    offset_ += sizeof(T);
    if constexpr (std::endian::native == std::endian::big) std::reverse(bits.begin(), bits.end());
    return std::bit_cast<T>(bits);
  }
  bool atEnd() { return in_.peek() == std::char_traits<char>::eof(); }
  [[noreturn]] void fail(const std::string& why) const {
    throw PrintFileError("prints file: " + why + " (byte " + std::to_string(offset_) + ")");
  }

 private:
  std::istream& in_;
  std::uint64_t offset_ = 0;
};

}  // namespace

void savePrints(const PrintTileStore& store, const SnowWindow& window, std::uint64_t refillQuanta, std::ostream& out) {
  out.write(kMagic.data(), kMagic.size());
  put(out, kPrintFileVersion);
  put(out, std::uint32_t(window.tileTexels()));
  put(out, window.texelSize());
  put(out, std::uint64_t(store.tileCount()));
  store.forEachOldestFirst([&](glm::ivec2 tile, const StoredTile& stored) {
    put(out, std::int32_t(tile.x));
    put(out, std::int32_t(tile.y));
    std::uint64_t missed = refillQuanta > stored.refillAtEviction ? refillQuanta - stored.refillAtEviction : 0;
    put(out, static_cast<std::uint32_t>(std::min<std::uint64_t>(missed, 0xFFFFFFFFu)));
    put(out, std::uint32_t(stored.heights.size()));
    for (std::uint16_t p : stored.positions) put(out, p);
    for (std::uint32_t h : stored.heights) put(out, h);
  });
  if (!out) throw PrintFileError("prints file: could not write");
}

std::size_t loadPrints(std::istream& in, const SnowWindow& window, std::uint64_t refillQuanta, PrintTileStore& store) {
  FieldReader r(in);
  std::array<char, 8> magic{};
  for (char& c : magic) c = static_cast<char>(r.read<std::uint8_t>("the magic"));
  if (magic != kMagic) r.fail("not a weathergen prints file (no WGPRINTS magic)");
  auto version = r.read<std::uint32_t>("the version");
  if (version != kPrintFileVersion)
    r.fail("version " + std::to_string(version) + " is not supported (this build reads " +
           std::to_string(kPrintFileVersion) + ")");
  auto tileTexels = r.read<std::uint32_t>("the tile size");
  auto texelSize = r.read<float>("the texel size");
  if (tileTexels != std::uint32_t(window.tileTexels()) || texelSize != window.texelSize())
    r.fail("saved with " + std::to_string(tileTexels) + "-texel tiles of " + std::to_string(texelSize) +
           " m texels; this map has " + std::to_string(window.tileTexels()) + " of " +
           std::to_string(window.texelSize()));
  const std::uint32_t texelsPerTile = tileTexels * tileTexels;
  auto tiles = r.read<std::uint64_t>("the tile count");
  PrintTileStore staged(store.budgetBytes());  // the file's tiles reach `store` only if all of it reads
  std::set<glm::ivec2, TileOrder> seen;  // grows with tiles actually read, never with the claimed count
  for (std::uint64_t t = 0; t < tiles; ++t) {
    glm::ivec2 tile;
    tile.x = r.read<std::int32_t>("a tile's x");  // two statements: the file's order
    tile.y = r.read<std::int32_t>("a tile's z");
    auto missed = r.read<std::uint32_t>("a tile's missed refill");
    auto count = r.read<std::uint32_t>("a tile's texel count");
    if (count == 0 || count > texelsPerTile)
      r.fail("tile " + std::to_string(t) + " claims " + std::to_string(count) + " texels (1 to " +
             std::to_string(texelsPerTile) + ")");
    StoredTile stored;
    stored.positions.reserve(count);
    stored.heights.reserve(count);
    for (std::uint32_t i = 0; i < count; ++i) {
      auto p = r.read<std::uint16_t>("a texel position");
      if (p >= texelsPerTile || (i > 0 && p <= stored.positions.back()))
        r.fail("tile " + std::to_string(t) + ": texel positions must increase and stay below " +
               std::to_string(texelsPerTile));
      stored.positions.push_back(p);
    }
    for (std::uint32_t i = 0; i < count; ++i) {
      auto h = r.read<std::uint32_t>("a texel");
      if (h == 0) r.fail("tile " + std::to_string(t) + ": an untouched texel is stored");
      stored.heights.push_back(h);
    }
    if (!seen.insert(tile).second)
      r.fail("tile " + std::to_string(tile.x) + "," + std::to_string(tile.y) + " appears twice");
    stored.refillAtEviction = refillQuanta >= missed ? refillQuanta - missed : 0;
    staged.put(tile, std::move(stored));
  }
  if (!r.atEnd()) r.fail("unexpected bytes after the last tile");
  std::vector<glm::ivec2> order;
  staged.forEachOldestFirst([&](glm::ivec2 tile, const StoredTile&) { order.push_back(tile); });
  for (glm::ivec2 tile : order) store.put(tile, *staged.take(tile));
  return std::size_t(tiles);
}

void savePrintsFile(const std::filesystem::path& path, const PrintTileStore& store, const SnowWindow& window,
                    std::uint64_t refillQuanta) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw PrintFileError("prints file: cannot write " + path.string());
  savePrints(store, window, refillQuanta, out);
}

std::size_t loadPrintsFile(const std::filesystem::path& path, const SnowWindow& window, std::uint64_t refillQuanta,
                           PrintTileStore& store) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw PrintFileError("prints file: cannot read " + path.string());
  return loadPrints(in, window, refillQuanta, store);
}

}  // namespace wg::snow
