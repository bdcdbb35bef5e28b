// turf-sim: the physics participant. Loads a scene, steps the MuJoCo world and
// publishes it on DDS; see sim_node.h for its topics (SSL and legged scenes),
// sim_startup.h for its flags and how it picks the kind of scene.
#include "participants/common/participant_main.h"
#include "participants/sim/sim_startup.h"

int main(int argc, char** argv) {
  turf::ParticipantMain participant(
      "turf-sim: the MuJoCo physics participant of turf (SSL and legged scenes), publishing on DDS");
  turf::SimCommandLine command_line;
  turf::AddSimFlags(participant, command_line);
  return participant.Run(argc, argv, [&] { return turf::RunSim(command_line); });
}
