// contacts.cpp: the contacts' module of setup (see contacts.h).
#include "setup/modules/contacts.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "setup/case_tables.h"
#include "setup/material_presets.h"
#include "setup/model.h"
#include "swarf/laws/hertz.h"

namespace swarf {

const std::vector<Key<ContactSettings>>& contact_keys() {
  using S = ContactSettings;
  static const std::vector<Key<S>> keys{
      {.name = "youngs_modulus",
       .field = &S::youngs_modulus,
       .unit = "Pa",
       .range = kModulus,
       .doc = "E of the particles in contacts (independent of `rod.youngs_modulus`)."},
      {.name = "poisson_ratio",
       .field = &S::poisson_ratio,
       .unit = "1",
       .range = in(-1, 0.5, "()"),
       .doc = "nu of the particles."},
      {.name = "restitution",
       .field = &S::restitution,
       .unit = "1",
       .range = in(0.01, 1, "[]"),
       .doc = "Normal coefficient of restitution e, the same at every impact speed. 1 means no damping."},
      {.name = "friction",
       .field = &S::friction,
       .unit = "1",
       .range = in(0.0, 10.0, "[]", "a judgement: measured coefficients are below 2"),
       .doc = "Coulomb coefficient mu. 0 means frictionless."},
      {.name = "friction_law",
       .field = &S::friction_law,
       .choices = {"spring", "regularized", "none"},
       .doc = "Tangential law, see [Tangential force](#tangential-force). `\"none\"` is frictionless whatever "
              "`friction` says."},
      {.name = "regularization_speed",
       .field = &S::regularization_speed,
       .unit = "m/s",
       .range = in(1e-9, 1e3, "[]", "1e-9 to 1e3 m/s"),
       .doc = "v0 of the `\"regularized\"` law."},
      {.name = "tangential_damping",
       .field = &S::tangential_damping,
       .unit = "1",
       .range = in(0, 10, "[]"),
       .doc = "`\"spring\"` law only: tangential dashpot as a multiple of the normal damping coefficient. 0 means "
              "none."},
      {.name = "skin",
       .field = &S::skin,
       .unit = "1",
       .range = in(0, 2, "(]"),
       .doc = "Verlet-list skin s as a fraction of the largest particle radius: s = `skin` x R_max (m)."},
      {.name = "sticking",
       .field = &S::sticking,
       .doc = "Cap the friction of the tool (triangle) contacts at the particle's share of the shear flow "
              "strength, 4 R^2 k(T): Zorev's sticking zone where mu times the pressure exceeds k "
              "([physics.md section 5](physics.md#5-hertz-contacts-with-restitution-damping-and-friction))."},
      {.name = "sticking_shear_strength",
       .field = &S::sticking_shear_strength,
       .unit = "Pa",
       .no_default = true,
       .default_note = "the preset's (A + B)/sqrt 3",
       .range = in(1e3, 1e11, "[]"),
       .doc = "k0, the workpiece's shear flow strength at room temperature; the preset's default is its "
              "Johnson-Cook flow stress at plastic strain 1 over sqrt 3 (von Mises)."},
      {.name = "sticking_softening_exponent",
       .field = &S::sticking_softening_exponent,
       .unit = "1",
       .no_default = true,
       .default_note = "the preset's Johnson-Cook m, else 1",
       .range = in(0.01, 10, "[]"),
       .doc = "m of the thermal factor 1 - T*^m of k (T* = (T - 293.15 K)/(T_melt - 293.15 K), clamped to "
              "[0, 1]); T is the particle's temperature ([heat]; without it the cap stays at k0)."},
      {.name = "sticking_melt_temperature",
       .field = &S::sticking_melt_temperature,
       .unit = "K",
       .no_default = true,
       .default_note = "the preset's",
       .range = in(300, 1e4, "[]"),
       .doc = "T_melt of the thermal factor of k."},
      {.name = "sticking_flow_zone",
       .field = &S::sticking_flow_zone,
       .doc = "Read the cap at the rake face's temperature instead of the particle's: the chip's flow zone "
              "(about 10 um, thinner than a particle) is hotter than the particle's mean by the contact's "
              "friction heat into the chip, (1 - `heat.tool_friction_share`) tau v_s, conducted over 2R/3: "
              "Delta T = (1 - s) tau v_s 2R / (3 K) with K = `heat.conductivity` (tau the face shear stress, v_s "
              "the slip speed). The cap solves tau = k0 Theta(T + Delta T). Needs [heat] "
              "([physics.md section 5](physics.md#5-hertz-contacts-with-restitution-damping-and-friction))."},
      {.name = "tool_friction_speeds",
       .field = &S::tool_friction_speeds,
       .unit = "m/s",
       .no_default = true,
       .default_note = "none: the tool's mu is `friction`",
       .range = in(0.0, 1e3, "[]", "a sliding speed, 0 to 1000 m/s"),
       .rule = "1 to 8 strictly increasing values; with `tool_friction_coefficients`; not with `friction_law` = "
               "`\"none\"`",
       .doc = "The tool (triangle) contacts' Coulomb coefficient as a table against the sliding speed v_s (the "
              "contact's relative tangential speed): the speeds of its points. Piecewise linear between them, "
              "constant outside; the sphere-sphere contacts keep `friction` "
              "([physics.md section 5](physics.md#5-hertz-contacts-with-restitution-damping-and-friction))."},
      {.name = "tool_friction_coefficients",
       .field = &S::tool_friction_coefficients,
       .unit = "1",
       .no_default = true,
       .default_note = "none",
       .range = in(0.0, 10.0, "[]", "a judgement: measured coefficients are below 2"),
       .rule = "as many as `tool_friction_speeds`",
       .doc = "The tool contacts' Coulomb coefficient mu at the points of `tool_friction_speeds` (a tribometer's "
              "friction against the sliding speed, measured at the cut's pressures)."},
  };
  return keys;
}

// [contact] sticking: its keys only with sticking = true; what they leave out from the preset.
static void read_sticking(TableReader& r, CaseSettings& cs) {
  ContactSettings& c = cs.contact;
  for (const char* key :
       {"sticking_shear_strength", "sticking_softening_exponent", "sticking_melt_temperature", "sticking_flow_zone"})
    if (r.has(key) && !c.sticking) r.fail(key, r.get(key), "is used only with contact.sticking = true");
  if (!c.sticking) return;
  const MaterialPreset* preset = cs.material.preset.empty() ? nullptr : find_material_preset(cs.material.preset);
  if (preset && !r.has("sticking_shear_strength"))
    c.sticking_shear_strength = (preset->jc_a + preset->jc_b) / std::sqrt(3.0);
  if (!r.has("sticking_softening_exponent")) c.sticking_softening_exponent = preset ? preset->jc_m : 1.0;
  if (preset && !r.has("sticking_melt_temperature")) c.sticking_melt_temperature = preset->melt_temperature;
  for (const char* key : {"sticking_shear_strength", "sticking_melt_temperature"})
    if (!r.has(key) && !preset)
      r.fail(key, nullptr,
             "sticking needs the shear flow strength (Pa) and the melting temperature (K): give them "
             "or material.preset");
}

// [contact] tool_friction_*: a table of the tool's mu against the sliding speed, whole or absent.
static void read_tool_friction(TableReader& r, const ContactSettings& c) {
  const auto& v = c.tool_friction_speeds;
  const auto& mu = c.tool_friction_coefficients;
  if (v.empty() && mu.empty()) return;
  if (v.empty() || mu.empty()) {
    const char* given = v.empty() ? "tool_friction_coefficients" : "tool_friction_speeds";
    r.fail(given, r.get(given),
           "the tool's friction table needs both tool_friction_speeds (m/s) and tool_friction_coefficients (1)");
  }
  if (v.size() > static_cast<std::size_t>(SpeedFriction::kMaxPoints))
    r.fail("tool_friction_speeds", r.get("tool_friction_speeds"),
           fmt::format("needs 1 to {} points, has {}", SpeedFriction::kMaxPoints, v.size()));
  if (mu.size() != v.size())
    r.fail(
        "tool_friction_coefficients", r.get("tool_friction_coefficients"),
        fmt::format("has {} values where tool_friction_speeds has {}: one coefficient per speed", mu.size(), v.size()));
  for (std::size_t i = 1; i < v.size(); ++i)
    if (!(v[i] > v[i - 1]))
      r.fail("tool_friction_speeds", r.get("tool_friction_speeds"),
             fmt::format("must be strictly increasing: value {} m/s is not above {} m/s", v[i], v[i - 1]));
  if (c.friction_law == "none")
    r.fail("tool_friction_speeds", r.get("tool_friction_speeds"),
           "a friction table needs a friction law: contact.friction_law is \"none\"");
}

void read_contact(const CaseInput& in, CaseSettings& cs) {
  if (const toml::table* t = in.table("contact")) {
    TableReader r = in.reader(t, "contact");
    cs.contact.enabled = true;
    r.read(contact_keys(), cs.contact);
    r.finish();  // (an unknown key, often a misspelt one, is named before the rules between keys)
    read_sticking(r, cs);
    read_tool_friction(r, cs.contact);
  }
}

void check_flow_zone(const CaseInput& in, const CaseSettings& cs) {
  if (!cs.contact.sticking_flow_zone || (cs.heat.present && cs.heat.enabled)) return;
  TableReader r = in.reader(in.table("contact"), "contact");
  r.know(contact_keys());
  r.fail("sticking_flow_zone", r.get("sticking_flow_zone"),
         "needs [heat] (the face's temperature rise is the friction heat over the workpiece's conductivity)");
}

// [contact]: the contact law's parameters.
static ContactParams contact_params(const CaseSettings& cs, const Particles& p) {
  ContactParams c;
  c.youngs_modulus = cs.contact.youngs_modulus;
  c.poisson_ratio = cs.contact.poisson_ratio;
  c.alpha = restitution_to_alpha(cs.contact.restitution);
  c.friction = cs.contact.friction;
  c.law = cs.contact.friction_law == "spring"        ? FrictionLaw::Spring
          : cs.contact.friction_law == "regularized" ? FrictionLaw::Regularized
                                                     : FrictionLaw::None;
  c.regularization_speed = cs.contact.regularization_speed;
  c.tool_friction.points = static_cast<int>(cs.contact.tool_friction_speeds.size());
  for (int k = 0; k < c.tool_friction.points; ++k) {
    c.tool_friction.speed[k] = cs.contact.tool_friction_speeds[k];
    c.tool_friction.mu[k] = cs.contact.tool_friction_coefficients[k];
  }
  c.tangential_damping = cs.contact.tangential_damping;
  double rmax = 0;
  for (double rr : p.radius) rmax = std::max(rmax, rr);
  for (const auto& f : cs.inflows) rmax = std::max(rmax, f.radius_max);
  c.skin = cs.contact.skin * rmax;
  if (cs.contact.sticking)
    c.sticking = StickingRule{.shear_strength = cs.contact.sticking_shear_strength,
                              .softening_exponent = cs.contact.sticking_softening_exponent,
                              .melt_temperature = cs.contact.sticking_melt_temperature,
                              .reference_temperature = 293.15,
                              .flow_zone = cs.contact.sticking_flow_zone ? (1.0 - cs.heat.tool_friction_share) * 2.0 /
                                                                               (3.0 * cs.heat.conductivity)
                                                                         : 0.0};
  return c;
}

void build_contacts(const CaseSettings& cs, World& world) {
  if (cs.contact.enabled) world.contact = contact_params(cs, world.particles);
  world.contacts = cs.contact.enabled;
}

std::string contacts_echo(const Model& m) {
  if (!m.contacts) return {};
  std::string s;
  const SpeedFriction& tf = m.contact.tool_friction;
  if (tf.points > 0) {
    s += "  tool friction against the sliding speed (piecewise linear, constant outside):";
    for (int k = 0; k < tf.points; ++k)
      s += fmt::format(" {:.4g} at {:.4g} m/s{}", tf.mu[k], tf.speed[k], k + 1 < tf.points ? "," : "\n");
  }
  if (!(m.contact.sticking.shear_strength > 0)) return s;
  const Derived& d = m.derived;
  s += fmt::format(
      "  sticking: tool friction capped at 4 R^2 k0 (1 - T*^{:.3g}), k0 = {:.4g} Pa, T_melt {:.5g} K: {:.4g} N per "
      "particle cold\n",
      m.contact.sticking.softening_exponent, m.contact.sticking.shear_strength, m.contact.sticking.melt_temperature,
      sticking_cap(m.contact.sticking, d.radius, 0.0));
  if (m.contact.sticking.flow_zone > 0)
    s += fmt::format(
        "  flow zone: the cap read at the face's temperature T + f R tau v_s, f R = {:.4g} K per MPa m/s (f = {:.4g} "
        "K m/W)\n",
        m.contact.sticking.flow_zone * d.radius * 1e6, m.contact.sticking.flow_zone);
  return s;
}

}  // namespace swarf
