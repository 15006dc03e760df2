// records.cpp: particles and rods as bytes (see records.h).
#include "swarf/domains/records.h"

#include <cstring>

namespace swarf {

namespace {

template <class T>
void put(Bytes& out, const T& v) {
  const std::size_t n = out.size();
  out.resize(n + sizeof(T));
  std::memcpy(out.data() + n, &v, sizeof(T));
}

template <class T>
std::size_t get(const std::byte* in, T& v) {
  std::memcpy(static_cast<void*>(&v), in, sizeof(T));  // (Eigen vectors: plain doubles)
  return sizeof(T);
}

}  // namespace

void pack_particle(Bytes& out, Particles& p, std::size_t i) {
  // One resize per record, not one per field: the halo packs every ghost's record each step.
  std::size_t bytes = 0;
  p.for_each_field([&](const char*, auto& v) { bytes += sizeof(v[i]); });
  std::size_t at = out.size();
  out.resize(at + bytes);
  p.for_each_field([&](const char*, auto& v) {
    std::memcpy(out.data() + at, &v[i], sizeof(v[i]));
    at += sizeof(v[i]);
  });
}

std::size_t unpack_particle(const std::byte* in, Particles& p, std::size_t i) {
  std::size_t at = 0;
  p.for_each_field([&](const char*, auto& v) { at += get(in + at, v[i]); });
  return at;
}

std::size_t unpack_new_particle(const std::byte* in, Particles& p) {
  std::size_t at = 0;
  p.for_each_field([&](const char*, auto& v) {
    v.emplace_back();
    at += get(in + at, v.back());
  });
  return at;
}

void pack_kinematics(Bytes& out, const Particles& p, std::size_t i) {
  const std::size_t at = out.size();
  out.resize(at + kKinematicsBytes);
  std::memcpy(out.data() + at, &p.position[i], sizeof(Vec3));
  std::memcpy(out.data() + at + sizeof(Vec3), &p.velocity[i], sizeof(Vec3));
  std::memcpy(out.data() + at + 2 * sizeof(Vec3), &p.acceleration[i], sizeof(Vec3));
}

std::size_t unpack_kinematics(const std::byte* in, Particles& p, std::size_t i) {
  std::memcpy(static_cast<void*>(&p.position[i]), in, sizeof(Vec3));
  std::memcpy(static_cast<void*>(&p.velocity[i]), in + sizeof(Vec3), sizeof(Vec3));
  std::memcpy(static_cast<void*>(&p.acceleration[i]), in + 2 * sizeof(Vec3), sizeof(Vec3));
  return kKinematicsBytes;
}

void pack_rod(Bytes& out, Rods& r, std::size_t k, std::int64_t key, std::array<std::int64_t, 2> end_id) {
  put(out, key);
  put(out, end_id);
  r.for_each_field([&](const char*, auto& v) { put(out, v[k]); });
}

std::size_t unpack_rod(const std::byte* in, RodPool& pool) {
  std::size_t at = 0;
  at += get(in + at, pool.key.emplace_back());
  at += get(in + at, pool.end_id.emplace_back());
  pool.rods.for_each_field([&](const char*, auto& v) {
    v.emplace_back();
    at += get(in + at, v.back());
  });
  return at;
}

}  // namespace swarf
