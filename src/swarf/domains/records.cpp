// records.cpp: particles and rods as bytes (see records.h).
#include "swarf/domains/records.h"

#include <cstring>
#include <type_traits>

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

std::size_t particle_record_bytes(Particles& p) {
  std::size_t bytes = 0;
  p.for_each_field([&](const char*, auto& v) { bytes += sizeof(typename std::decay_t<decltype(v)>::value_type); });
  return bytes;
}

std::size_t write_particle(std::byte* out, Particles& p, std::size_t i) {
  std::size_t at = 0;
  p.for_each_field([&](const char*, auto& v) {
    std::memcpy(out + at, &v[i], sizeof(v[i]));
    at += sizeof(v[i]);
  });
  return at;
}

void pack_particle(Bytes& out, Particles& p, std::size_t i) {
  // One resize per record, not one per field: the halo packs every ghost's record each step.
  const std::size_t at = out.size();
  out.resize(at + particle_record_bytes(p));
  write_particle(out.data() + at, p, i);
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

void pack_kinematics(Bytes& out, const Particles& p, std::size_t i, HaloFields f) {
  std::size_t at = out.size();
  out.resize(at + f.bytes());
  const auto put = [&](const void* v, std::size_t n) {
    std::memcpy(out.data() + at, v, n);
    at += n;
  };
  if (f.kinematics) {
    put(&p.position[i], sizeof(Vec3));
    put(&p.velocity[i], sizeof(Vec3));
    put(&p.acceleration[i], sizeof(Vec3));
  }
  if (f.omega) put(&p.omega[i], sizeof(Vec3));
  if (f.temperature) put(&p.temperature[i], sizeof(double));
}

std::size_t unpack_kinematics(const std::byte* in, Particles& p, std::size_t i, HaloFields f) {
  const std::byte* at = in;
  const auto get = [&](void* v, std::size_t n) {
    std::memcpy(v, at, n);
    at += n;
  };
  if (f.kinematics) {
    get(static_cast<void*>(&p.position[i]), sizeof(Vec3));
    get(static_cast<void*>(&p.velocity[i]), sizeof(Vec3));
    get(static_cast<void*>(&p.acceleration[i]), sizeof(Vec3));
  }
  if (f.omega) get(static_cast<void*>(&p.omega[i]), sizeof(Vec3));
  if (f.temperature) get(&p.temperature[i], sizeof(double));
  return f.bytes();
}

std::size_t rod_record_bytes(Rods& r) {
  std::size_t bytes = sizeof(std::int64_t) + sizeof(std::array<std::int64_t, 2>);
  r.for_each_field([&](const char*, auto& v) { bytes += sizeof(typename std::decay_t<decltype(v)>::value_type); });
  return bytes;
}

std::size_t write_rod(std::byte* out, Rods& r, std::size_t k, std::int64_t key, std::array<std::int64_t, 2> end_id) {
  std::memcpy(out, &key, sizeof key);
  std::memcpy(out + sizeof key, &end_id, sizeof end_id);
  std::size_t at = sizeof key + sizeof end_id;
  r.for_each_field([&](const char*, auto& v) {
    std::memcpy(out + at, &v[k], sizeof(v[k]));
    at += sizeof(v[k]);
  });
  return at;
}

void pack_rod(Bytes& out, Rods& r, std::size_t k, std::int64_t key, std::array<std::int64_t, 2> end_id) {
  const std::size_t at = out.size();  // (one resize per record, as pack_particle)
  out.resize(at + rod_record_bytes(r));
  write_rod(out.data() + at, r, k, key, end_id);
}

RodHead rod_head(const std::byte* in) {
  RodHead h;
  std::memcpy(&h.key, in, sizeof h.key);
  std::memcpy(&h.end_id, in + sizeof h.key, sizeof h.end_id);
  return h;
}

std::size_t unpack_rod_over(const std::byte* in, Rods& r, std::size_t k) {
  std::size_t at = sizeof(std::int64_t) + sizeof(std::array<std::int64_t, 2>);
  r.for_each_field([&](const char*, auto& v) { at += get(in + at, v[k]); });
  return at;
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
