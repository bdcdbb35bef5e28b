// rcssserver3d's contact law (ODE soft contacts with force-dependent slip) carried out in MuJoCo's constraint rows,
// so that a robot's feet meet the ground as they do on the reference server (shared/protocols/simspark.md, "Nao
// physical model"; the parameters are the reference's own, from its scene files).
//
// ODE, as rcssserver3d steps it: a contact between two surfaces mixes their parameters (both set: the mean; one set:
// that one; none: the world's ERP and CFM, no slip), the friction coefficient is infinite, and
//  - normal: ERP and CFM at the reference step h_ref are a spring and a damper, k = ERP / (h_ref CFM) and
//    c = (1 - ERP) / CFM, on the penetration beyond the world's surface layer; they only push;
//  - tangential: force-dependent slip, the contact slides at v = slip F (no Coulomb bound).
// In MuJoCo (elliptic cones; the Newton solver's row law J a = aref - R f), after mj_step1 each such contact's rows
// get the R and aref that make that law hold implicitly over MuJoCo's step h:
//   normal      R = 1 / (h (k h + c))    aref = -(k r / (k h + c) + v) / h    (r <= 0: penetration beyond the layer)
//   tangential  R = slip / h             aref = -v / h                        (then v' = -slip F)
// and a friction coefficient so large that the cone never binds. ODE's bounce, in either law: a contact coming in
// faster than bounce_vel gets a normal row that leaves at least bounce times that speed (stiff, aref to it). The
// ball's contacts follow the law when the scene sets a ball surface (rsg/agent/ball.rsg: soft ERP 0.5, CFM 0.05,
// slip 0.6, bounce 0.8 above 0.8 m/s; mixed with the ground's or a robot's, which set no bounce, it slips at
// 0.30 m/(s N) and bounces at 0.8; its ERP and CFM act only under `law: ode`); contacts of the goals and walls keep
// MuJoCo's own law (the reference's posts have a default surface: not modelled). Not modelled: torsional and
// rolling friction (ODE has none: those rows carry no force).
// `law: ode_friction` (OdeContactLaw::ode_normal false) rewrites only the tangential rows and keeps MuJoCo's normal
// row: with it UT Austin Villa's agents stay upright 64-77 % of a 4-agent match (full law 35 %, MuJoCo's 50-55 %;
// README, issue 12).
#pragma once

#include <mujoco/mujoco.h>

#include <cstdint>
#include <vector>

#include "core/legged/legged_scene.h"

namespace turf {

// The parameters of a contact between two surfaces, mixed as ODE does, as a spring, a damper and a slip.
struct OdeMixed {
  double k = 0.0;           // N/m
  double c = 0.0;           // N s/m
  double slip = 0.0;        // m/(s N); 0: no slip
  double bounce = 0.0;      // 0: none
  double bounce_vel = 0.0;  // m/s
};
OdeMixed MixOdeSurfaces(const OdeContactLaw& law, const OdeSurface& a, const OdeSurface& b);

class OdeContacts {
 public:
  // Sorts the model's geoms: the robots' (robot_roots: their base bodies), the floor's and the ball's (-1: none).
  OdeContacts(const mjModel* model, const OdeContactLaw& law, const std::vector<int>& robot_roots, int floor_geom,
              int ball_geom);

  // After mj_step1, before the solver (mj_step2): rewrites the rows of every contact the law covers.
  void Apply(const mjModel* model, mjData* data) const;

 private:
  enum class Surface : uint8_t { kNone, kRobot, kGround, kBall };
  const OdeSurface& Of(Surface s) const {
    return s == Surface::kRobot ? law_.robot : s == Surface::kBall ? law_.ball : law_.ground;
  }

  OdeContactLaw law_;
  std::vector<Surface> surface_of_geom_;
};

}  // namespace turf
