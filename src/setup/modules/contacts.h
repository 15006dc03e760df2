// contacts.h: the contacts' module of setup: [contact]'s settings, key table, rules (sticking and
// what the material preset fills) and build into the World's contact parameters. Listed once in
// each central list: parse_case (case_config.cpp), the key rows (case_key_text.cpp), the case
// echo (app/case_echo.cpp), build_model (model.cpp) and the setup printout (app/setup_report.cpp).
#pragma once

#include <string>
#include <vector>

#include "setup/key.h"

namespace swarf {

struct CaseInput;
struct CaseSettings;
struct Model;
struct World;

/// [contact]: Hertz contacts with friction between unbonded particles and with meshes.
struct ContactSettings {
  bool enabled = false;           ///< true when the table is present
  double youngs_modulus = 200e9;  ///< E of the particles' material for contacts, Pa
  double poisson_ratio = 0.3;     ///< nu of the particles, 1
  double restitution = 0.5;       ///< normal coefficient of restitution, 1 (0.01..1)
  double friction = 0.0;          ///< Coulomb coefficient mu, 1
  std::string
      friction_law = "spring";  ///< "spring" (Cundall-Strack, capped by Coulomb), "regularized" (tanh slip law), "none"
  double regularization_speed = 1e-3;  ///< v0 in tanh(|v_t|/v0) of the regularized law, m/s
  double tangential_damping = 0.0;  ///< spring law: tangential dashpot as a multiple of the normal damping coefficient, 1
  double skin = 0.2;                ///< Verlet-list skin as a fraction of the largest radius, 1
  bool sticking = false;            ///< cap the tool contacts' friction at the shear flow strength
  double sticking_shear_strength = 0.0;      ///< k0, Pa; 0 = not given (the preset's)
  double sticking_softening_exponent = 0.0;  ///< m, 1; 0 = not given (the preset's, else 1)
  double sticking_melt_temperature = 0.0;    ///< T_melt, K; 0 = not given (the preset's)
  bool sticking_flow_zone = false;  ///< the cap at the face's temperature (a sub-particle flow zone), needs [heat]
  std::vector<double> tool_friction_speeds;        ///< sliding speeds of the tool's mu table, m/s (empty: none)
  std::vector<double> tool_friction_coefficients;  ///< the tool's mu at those speeds, 1
};

const std::vector<Key<ContactSettings>>& contact_keys();

/// Reads [contact] when present and checks its rules; after [material] (its preset) and [[group]].
void read_contact(const CaseInput& in, CaseSettings& cs);

/// [contact] sticking_flow_zone's rule between tables: it needs [heat] (its conductivity and the
/// tool's share of the friction heat); after read_heat.
void check_flow_zone(const CaseInput& in, const CaseSettings& cs);

/// The World's contact switch and, with [contact], its parameters (the skin from the particles'
/// and the inflows' largest radius).
void build_contacts(const CaseSettings& cs, World& world);

/// The setup printout's lines on the contacts (empty when there is nothing to say).
std::string contacts_echo(const Model& m);

}  // namespace swarf
