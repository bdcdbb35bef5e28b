#include "core/legged/ode_contacts.h"

#include <algorithm>
#include <cmath>

namespace turf {

namespace {

// ODE's mixing of one parameter: the mean if both surfaces set it, the one set, or the fallback.
double MixValue(double a, double b, double fallback) {
  if (a >= 0 && b >= 0) return 0.5 * (a + b);
  if (a >= 0) return a;
  if (b >= 0) return b;
  return fallback;
}

// Large enough that the elliptic cone never binds (ODE's mu = infinity) and still well inside double's range.
constexpr double kUnboundedFriction = 1e4;
// A tangential row without slip: as stiff as MuJoCo allows (the servo stage's stiff rows do the same).
constexpr double kStiffCompliance = 1e-4;

}  // namespace

OdeContacts::OdeContacts(const mjModel* model, const OdeContactLaw& law, const std::vector<int>& robot_roots,
                         int floor_geom, int ball_geom)
    : law_(law), surface_of_geom_(model->ngeom, Surface::kNone) {
  for (int g = 0; g < model->ngeom; ++g) {
    const int root = model->body_rootid[model->geom_bodyid[g]];
    if (std::find(robot_roots.begin(), robot_roots.end(), root) != robot_roots.end())
      surface_of_geom_[g] = Surface::kRobot;
  }
  if (floor_geom >= 0) surface_of_geom_[floor_geom] = Surface::kGround;
  const OdeSurface& b = law.ball;
  if (ball_geom >= 0 && (b.erp >= 0 || b.cfm >= 0 || b.slip >= 0)) surface_of_geom_[ball_geom] = Surface::kBall;
}

OdeMixed MixOdeSurfaces(const OdeContactLaw& law, const OdeSurface& a, const OdeSurface& b) {
  const double erp = MixValue(a.erp, b.erp, law.world_erp);
  const double cfm = MixValue(a.cfm, b.cfm, law.world_cfm);
  OdeMixed m;
  m.k = erp / (law.reference_step * cfm);
  m.c = (1.0 - erp) / cfm;
  m.slip = MixValue(a.slip, b.slip, 0.0);
  m.bounce = MixValue(a.bounce, b.bounce, 0.0);
  m.bounce_vel = MixValue(a.bounce_vel, b.bounce_vel, 0.0);
  return m;
}

void OdeContacts::Apply(const mjModel* model, mjData* data) const {
  const double h = model->opt.timestep;
  for (int i = 0; i < data->ncon; ++i) {
    mjContact& con = data->contact[i];
    const Surface s1 = surface_of_geom_[con.geom1];
    const Surface s2 = surface_of_geom_[con.geom2];
    if (s1 == Surface::kNone || s2 == Surface::kNone || con.efc_address < 0 || con.dim < 3) continue;
    const OdeMixed mixed = MixOdeSurfaces(law_, Of(s1), Of(s2));
    const int n = con.efc_address;
    // Normal row: the spring-damper on the penetration beyond the surface layer, implicit over h (ode_friction:
    // MuJoCo's own row, from the geoms' solref and solimp).
    if (law_.ode_normal) {
      const double r = std::min(0.0, data->efc_pos[n] - data->efc_margin[n] + law_.surface_layer);
      const double khc = mixed.k * h + mixed.c;
      data->efc_R[n] = 1.0 / (h * khc);
      data->efc_aref[n] = -(mixed.k * r / khc + data->efc_vel[n]) / h;
    }
    // ODE's bounce (dContactBounce): coming in faster than bounce_vel, leave at least bounce times that speed.
    const double incoming = -data->efc_vel[n];
    if (mixed.bounce > 0 && incoming > mixed.bounce_vel) {
      const double aref = (mixed.bounce * incoming - data->efc_vel[n]) / h;
      if (aref > data->efc_aref[n]) {
        data->efc_aref[n] = aref;
        data->efc_R[n] = data->efc_diagApprox[n] * kStiffCompliance;
      }
    }
    // Tangential rows: force-dependent slip. Rows beyond them (torsion, rolling) carry no force, as in ODE.
    for (int j = 1; j < con.dim; ++j) {
      const int row = n + j;
      if (j <= 2) {
        data->efc_R[row] = mixed.slip > 0 ? mixed.slip / h : data->efc_diagApprox[row] * kStiffCompliance;
        data->efc_aref[row] = -data->efc_vel[row] / h;
      } else {
        data->efc_R[row] = 1e12;
        data->efc_aref[row] = 0.0;
      }
    }
    for (int j = 0; j < con.dim; ++j) data->efc_D[n + j] = 1.0 / data->efc_R[n + j];
    for (int j = 0; j < 5; ++j) con.friction[j] = kUnboundedFriction;
    // MuJoCo's regularised cone coefficient (mj_makeImpedance's rule for elliptic cones), from the new rows.
    con.mu = kUnboundedFriction * std::sqrt(data->efc_R[n + 1] / data->efc_R[n]);
  }
}

}  // namespace turf
