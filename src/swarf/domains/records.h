// records.h: a particle or a rod as bytes, to move between domains (halo exchange, migration).
//
// A particle's record is every per-particle field (Particles::for_each_field: the one list of
// them, so a new field travels without a change here), copied bit for bit. A rod's record is its
// key (its place in the global rod order), its ends' particle ids and every per-rod field
// (Rods::for_each_field). Sending whole records costs bytes (about 300 per particle) but leaves
// no field a ghost or a migrant could lose.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "swarf/core/comm.h"
#include "swarf/state/particles.h"
#include "swarf/state/rods.h"

namespace swarf {

/// Appends particle i's record to 'out'.
void pack_particle(Bytes& out, Particles& p, std::size_t i);
/// The bytes of one particle's record; writes particle i's record at 'out' (that many bytes).
std::size_t particle_record_bytes(Particles& p);
std::size_t write_particle(std::byte* out, Particles& p, std::size_t i);
/// Writes the record at 'in' over particle i; returns the bytes read.
std::size_t unpack_particle(const std::byte* in, Particles& p, std::size_t i);
/// Appends the record at 'in' as a new particle of p; returns the bytes read.
std::size_t unpack_new_particle(const std::byte* in, Particles& p);

/// The fields of the halo's record: always position, velocity and acceleration (what a step
/// changes and the next step reads of a ghost); with rotations the angular velocity (its
/// contacts read it), with heat the temperature (its rods' and contacts' laws read it). The other
/// fields of a ghost stay as it arrived: constant ones (mass, radius, ...) exact, its orientation,
/// the plastic strain's window and the force its own, which nothing of an owned particle reads.
struct HaloFields {
  bool omega = false, temperature = false;
  bool kinematics = true;  ///< false: only the fields flagged above (the conduction's temperatures midway)
  std::size_t bytes() const {
    return ((kinematics ? 3 : 0) + (omega ? 1 : 0)) * sizeof(Vec3) + (temperature ? sizeof(double) : 0);
  }
};
/// Appends the halo's record of particle i.
void pack_kinematics(Bytes& out, const Particles& p, std::size_t i, HaloFields f);
/// Writes the halo's record at 'in' over particle i; returns the bytes read.
std::size_t unpack_kinematics(const std::byte* in, Particles& p, std::size_t i, HaloFields f);

/// Rods gathered from records: their per-rod fields (in 'rods', whose 'ends' stay empty), keys
/// and end ids, in the order received.
struct RodPool {
  Rods rods;
  std::vector<std::int64_t> key;
  std::vector<std::array<std::int64_t, 2>> end_id;
};

/// Appends rod k's record with its key and its ends' ids.
void pack_rod(Bytes& out, Rods& r, std::size_t k, std::int64_t key, std::array<std::int64_t, 2> end_id);
/// The bytes of one rod's record; writes rod k's record at 'out' (that many bytes).
std::size_t rod_record_bytes(Rods& r);
std::size_t write_rod(std::byte* out, Rods& r, std::size_t k, std::int64_t key, std::array<std::int64_t, 2> end_id);
/// Appends the record at 'in' to the pool; returns the bytes read.
std::size_t unpack_rod(const std::byte* in, RodPool& pool);
/// A rod record's key and end ids.
struct RodHead {
  std::int64_t key = 0;
  std::array<std::int64_t, 2> end_id{};
};
RodHead rod_head(const std::byte* in);
/// Writes the per-rod fields of the record at 'in' over rod k of r (its ends stay); returns the bytes read.
std::size_t unpack_rod_over(const std::byte* in, Rods& r, std::size_t k);

}  // namespace swarf
