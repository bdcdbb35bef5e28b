/* A second DDS implementation reading turf's rt/low_state (issue 15: the wire contract across vendors). Built with
 * Debian's Cyclone DDS from turf's own idl/booster/BoosterLowLevel.idl (idlc), it subscribes as any Booster SDK user
 * on another vendor would, prints the first sample it gets and exits 0; exit 1 if none arrives within the timeout.
 *   cyclone_low_state_reader DOMAIN TIMEOUT_S
 * Output: "joints <serial> <parallel> head_pitch <q> acc_z <acc[2]>" */
#include <dds/dds.h>
#include <stdio.h>
#include <stdlib.h>

#include "BoosterLowLevel.h"

int main(int argc, char** argv) {
  if (argc != 3) {
    fprintf(stderr, "usage: %s DOMAIN TIMEOUT_S\n", argv[0]);
    return 2;
  }
  const dds_domainid_t domain = (dds_domainid_t)atoi(argv[1]);
  const double timeout_s = atof(argv[2]);
  const dds_entity_t participant = dds_create_participant(domain, NULL, NULL);
  if (participant < 0) {
    fprintf(stderr, "dds_create_participant: %s\n", dds_strretcode(-participant));
    return 1;
  }
  const dds_entity_t topic =
      dds_create_topic(participant, &booster_interface_msg_dds__LowState__desc, "rt/low_state", NULL, NULL);
  dds_qos_t* qos = dds_create_qos();
  dds_qset_reliability(qos, DDS_RELIABILITY_BEST_EFFORT, 0);
  const dds_entity_t reader = dds_create_reader(participant, topic, qos, NULL);
  dds_delete_qos(qos);
  if (topic < 0 || reader < 0) {
    fprintf(stderr, "topic or reader: %s\n", dds_strretcode(topic < 0 ? -topic : -reader));
    return 1;
  }
  /* Wait on the reader's data (a waitset with the deadline), then take. */
  const dds_entity_t waitset = dds_create_waitset(participant);
  const dds_entity_t readable = dds_create_readcondition(reader, DDS_ANY_STATE);
  dds_waitset_attach(waitset, readable, reader);
  void* samples[1] = {NULL};
  dds_sample_info_t info[1];
  const dds_time_t deadline = dds_time() + (dds_time_t)(timeout_s * 1e9);
  int status = 1;
  while (status != 0 && dds_time() < deadline) {
    if (dds_waitset_wait_until(waitset, NULL, 0, deadline) <= 0) break;
    const dds_return_t n = dds_take(reader, samples, info, 1, 1);
    if (n <= 0) continue;
    if (info[0].valid_data) {
      const booster_interface_msg_dds__LowState_* s = samples[0];
      printf("joints %u %u head_pitch %.4f acc_z %.3f\n", s->motor_state_serial._length,
             s->motor_state_parallel._length,
             s->motor_state_serial._length > 1 ? s->motor_state_serial._buffer[1].q : -99.0f, s->imu_state.acc[2]);
      status = 0;
    }
    dds_return_loan(reader, samples, n);
  }
  if (status != 0) fprintf(stderr, "no rt/low_state within %.0f s\n", timeout_s);
  dds_delete(participant);
  return status;
}
