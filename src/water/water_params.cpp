// Parameter tables of the water subsystem (see core/params.hpp). Keys are distinct from every
// other section's unless they mean the same thing with the same unit (sea_level).
#include "core/params.hpp"
#include "water/droplets.hpp"
#include "water/flow.hpp"
#include "water/stream_power.hpp"
#include "water/thermal.hpp"

namespace sansui::water {

const params::Table<FlowParams>& parameter_table(const FlowParams*) {
  using P = FlowParams;
  static const auto table =
      params::Table<P>("flow",
                       "Flow routing and rivers: priority-flood, D8 and multiple-flow-direction drainage area, channels, Strahler order")
          .add(params::field("sea_level", &P::sea_level_m)
                   .in(-1e5, 1e5)
                   .units("m")
                   .unset("none: only the map's edge drains")
                   .doc("Cells below this height are sea: water leaves the map there")
                   .grouped("water"))
          .add(params::field("channel_area", &P::channel_area_m2)
                   .at_most(1e14)
                   .above(0)
                   .units("m^2")
                   .doc("Drainage area at which a channel (a river cell) begins")
                   .grouped("water"))
          .add(params::field("runoff", &P::runoff_mm_per_yr)
                   .at_least(0)
                   .at_most(1e5)
                   .units("mm/yr")
                   .doc("Runoff per unit area: a river's discharge is its drainage area times this")
                   .grouped("water"))
          .add(params::field("flow_exponent", &P::flow_exponent)
                   .above(0)
                   .at_most(100)
                   .no_unit()
                   .doc("Freeman's exponent p of multiple-flow-direction routing: larger concentrates the flow")
                   .grouped("water"));
  return table;
}

void FlowParams::validate() const {
  params::validate(*this);
}

const params::Table<StreamPowerParams>& parameter_table(const StreamPowerParams*) {
  using P = StreamPowerParams;
  static const auto table =
      params::Table<P>("erosion",
                       "Landscape evolution: implicit stream-power incision (Braun & Willett 2013), deposition, hillslope diffusion")
          .add(params::field("erodibility", &P::erodibility)
                   .at_least(0)
                   .at_most(1)
                   .units("m^(1-2m)/yr")
                   .doc("Erodibility K of dz/dt = U - K A^m S^n: larger carves faster")
                   .grouped("erosion"))
          .add(params::field("area_exponent", &P::area_exponent)
                   .in(0, 2)
                   .no_unit()
                   .doc("Drainage-area exponent m; m/n is the concavity of river profiles (0.45 is typical)")
                   .grouped("erosion"))
          .add(params::field("slope_exponent", &P::slope_exponent)
                   .in(0.5, 4)
                   .no_unit()
                   .doc("Slope exponent n (1: linear, solved exactly; otherwise by Newton's method per cell)")
                   .grouped("erosion"))
          .add(params::field("uplift", &P::uplift_m_per_yr)
                   .at_least(0)
                   .at_most(1)
                   .units("m/yr")
                   .doc("Rock uplift U, the same everywhere (an uplift map replaces it)")
                   .grouped("erosion"))
          .add(params::field("diffusivity", &P::diffusivity_m2_per_yr)
                   .at_least(0)
                   .at_most(1e4)
                   .units("m^2/yr")
                   .unset("3 cell sizes squared per response time: the same rounding on any grid")
                   .doc("Hillslope diffusivity D: soil creep rounds ridges and fills hollows")
                   .grouped("erosion"))
          .add(params::field("deposition", &P::deposition)
                   .in(0, 10)
                   .no_unit()
                   .doc("Deposition coefficient G (Yuan et al. 2019): 0 none; 1 builds fans and valley floors")
                   .grouped("erosion"))
          .add(params::field("time_step", &P::time_step_yr)
                   .above(0)
                   .at_most(1e9)
                   .units("yr")
                   .doc("Length of one erosion step")
                   .grouped("erosion"))
          .add(params::field("erosion_steps", &P::steps).in(0, 100000).doc("Number of erosion steps").grouped("erosion"))
          .add(params::field("sea_level", &P::sea_level_m)
                   .in(-1e5, 1e5)
                   .units("m")
                   .unset("none: only the map's edge is base level")
                   .doc("Cells below this height are sea: fixed base level, sediment reaching it leaves")
                   .grouped("erosion"));
  return table;
}

void StreamPowerParams::validate() const {
  params::validate(*this);
}

const params::Table<ThermalParams>& parameter_table(const ThermalParams*) {
  using P = ThermalParams;
  static const auto table =
      params::Table<P>("thermal", "Thermal erosion: material above the angle of repose slides downhill")
          .add(params::field("talus_angle", &P::talus_angle_deg)
                   .in(0, 89)
                   .units("deg")
                   .doc("Angle of repose: slopes steeper than this shed material")
                   .grouped("thermal"))
          .add(params::field("thermal_iterations", &P::iterations).in(0, 10000).doc("Iterations of thermal erosion").grouped("thermal"))
          .add(params::field("thermal_rate", &P::rate)
                   .above(0)
                   .at_most(0.5)
                   .no_unit()
                   .doc("Fraction of the excess a cell sheds per iteration")
                   .grouped("thermal"));
  return table;
}

void ThermalParams::validate() const {
  params::validate(*this);
}

const params::Table<DropletParams>& parameter_table(const DropletParams*) {
  using P = DropletParams;
  static const auto table =
      params::Table<P>("droplets", "Droplet hydraulic erosion (Beyer 2015): particles carrying sediment, depositing when they slow")
          .add(params::field("droplets", &P::droplets)
                   .in(0, 1e9)
                   .unset("droplets_per_cell times the number of cells")
                   .doc("Number of droplets")
                   .grouped("droplets"))
          .add(params::field("droplets_per_cell", &P::droplets_per_cell)
                   .in(0, 100)
                   .no_unit()
                   .doc("Droplets per cell of the grid, when droplets is unset: the same rills on any grid size")
                   .grouped("droplets"))
          .add(params::field("droplet_seed", &P::seed).doc("Random seed of the droplets' starting points").grouped("droplets"))
          .add(params::field("droplet_lifetime", &P::lifetime)
                   .in(1, 1000)
                   .doc("Steps (cells travelled) before a droplet is gone")
                   .grouped("droplets"))
          .add(params::field("droplet_inertia", &P::inertia)
                   .in(0, 1)
                   .no_unit()
                   .doc("How much of its direction a droplet keeps against the slope")
                   .grouped("droplets"))
          .add(params::field("sediment_capacity", &P::capacity)
                   .in(0, 1000)
                   .no_unit()
                   .doc("Sediment a droplet can carry per unit of drop x speed x water")
                   .grouped("droplets"))
          .add(params::field("min_sediment_capacity", &P::min_capacity)
                   .in(0, 1000)
                   .no_unit()
                   .doc("Capacity on flat ground, in cell sizes")
                   .grouped("droplets"))
          .add(params::field("droplet_erosion", &P::erosion_rate)
                   .in(0, 1)
                   .no_unit()
                   .doc("Fraction of its free capacity a droplet takes up per step")
                   .grouped("droplets"))
          .add(params::field("droplet_deposition", &P::deposition_rate)
                   .in(0, 1)
                   .no_unit()
                   .doc("Fraction of its surplus load a droplet drops per step")
                   .grouped("droplets"))
          .add(params::field("evaporation", &P::evaporation)
                   .in(0, 1)
                   .no_unit()
                   .doc("Fraction of a droplet's water lost per step")
                   .grouped("droplets"))
          .add(params::field("droplet_gravity", &P::gravity)
                   .above(0)
                   .at_most(1000)
                   .no_unit()
                   .doc("Acceleration of a droplet per unit of drop")
                   .grouped("droplets"));
  return table;
}

void DropletParams::validate() const {
  params::validate(*this);
}

}  // namespace sansui::water
