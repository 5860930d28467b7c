#include "core/state_io.hpp"

#include <istream>
#include <ostream>

#include "core/error.hpp"

namespace plyimpact {

namespace {

constexpr char kMagic[] = "plyimpact-state-1\n";

void write_u64(std::ostream& out, std::uint64_t v) { out.write(reinterpret_cast<const char*>(&v), sizeof v); }

bool read_u64(std::istream& in, std::uint64_t& v) {
  return bool(in.read(reinterpret_cast<char*>(&v), sizeof v));
}

}  // namespace

std::string StatePath::path(std::string_view name) const {
  std::string p;
  for (const auto& g : groups_) p += g + "/";
  return p.append(name);
}

StateWriter::StateWriter(std::ostream& out) : out_(out) { out_.write(kMagic, sizeof kMagic - 1); }

void StateWriter::block(std::string_view name, std::size_t elem_size, std::size_t count, void* data, Resize,
                        void*) {
  const std::string p = path(name);
  write_u64(out_, p.size());
  out_.write(p.data(), std::streamsize(p.size()));
  write_u64(out_, elem_size);
  write_u64(out_, count);
  if (count > 0) out_.write(static_cast<const char*>(data), std::streamsize(elem_size * count));
  if (!out_) throw RunError(msg() << "cannot write the run state (block '" << p << "')");
}

StateReader::StateReader(std::istream& in, std::string source) : in_(in), source_(std::move(source)) {
  std::string magic(sizeof kMagic - 1, '\0');
  if (!in_.read(magic.data(), std::streamsize(magic.size())) || magic != kMagic)
    throw InputError(msg() << source_ << ": not a plyimpact run state (expected the header '"
                           << std::string_view(kMagic, sizeof kMagic - 2) << "')");
}

void StateReader::block(std::string_view name, std::size_t elem_size, std::size_t count, void* data, Resize resize,
                        void* owner) {
  const std::string expected = path(name);
  std::uint64_t length = 0, stored_size = 0, stored_count = 0;
  std::string stored;
  if (read_u64(in_, length) && length < (1u << 16)) {
    stored.resize(length);
    in_.read(stored.data(), std::streamsize(length));
  }
  if (!in_ || !read_u64(in_, stored_size) || !read_u64(in_, stored_count))
    throw InputError(msg() << source_ << ": the run state ends before block '" << expected
                           << "' (truncated file, or written by a scene with fewer blocks)");
  if (stored != expected || stored_size != elem_size)
    throw InputError(msg() << source_ << ": run state does not match this model: expected block '" << expected
                           << "' of " << elem_size << "-byte values, found '" << stored << "' of " << stored_size
                           << "-byte values (written by another scene or program version)");
  if (stored_count != count) {
    if (!resize)
      throw InputError(msg() << source_ << ": run state does not match this model: block '" << expected << "' has "
                             << stored_count << " values, the model has " << count);
    data = resize(owner, stored_count);
  }
  if (stored_count > 0 && !in_.read(static_cast<char*>(data), std::streamsize(elem_size * stored_count)))
    throw InputError(msg() << source_ << ": the run state ends inside block '" << expected << "' (truncated file)");
}

void StateDigest::add(const void* data, std::size_t bytes) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < bytes; ++i) {
    hash_ ^= p[i];
    hash_ *= 1099511628211ull;  // FNV prime
  }
}

void StateDigest::block(std::string_view name, std::size_t elem_size, std::size_t count, void* data, Resize,
                        void*) {
  const std::string p = path(name);
  add(p.data(), p.size());
  const std::uint64_t sizes[2] = {elem_size, count};
  add(sizes, sizeof sizes);
  if (count > 0) add(data, elem_size * count);
}

}  // namespace plyimpact
