"""What every turf environment shares: one Sim (self.sim), the snapshot each reset starts from (self.start), and
a reset that re-seeds the Sim when asked for a new seed."""

from .spaces import EnvBase


class SimEnv(EnvBase):
    def _attach(self, sim, max_episode_steps, render_mode):
        self.render_mode = render_mode
        self.max_episode_steps = max_episode_steps
        self.sim = sim
        self._take_start()

    def _take_start(self):
        """Keeps the snapshot each reset starts from: by default the Sim as it is now."""
        self.start = self.sim.save()

    def _restart(self, seed):
        """The observation at the start snapshot; a new seed re-seeds the Sim and takes a new start first."""
        if seed is not None and seed != self.sim.seed:
            self.sim.reset(seed=seed)
            self._take_start()
        return self.sim.restore(self.start)
