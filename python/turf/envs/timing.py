"""Environment steps of a fixed length in physics steps: 1/60 s of 2 ms steps is 8 or 9 of them, so that
k environment steps are always round(k * env_dt / physics_dt) physics steps (no drift)."""


class StepClock:
    def __init__(self, env_dt, physics_dt):
        self.ratio = env_dt / physics_dt
        self.k = 0

    def reset(self):
        self.k = 0

    def next(self):
        n = int(round((self.k + 1) * self.ratio)) - int(round(self.k * self.ratio))
        self.k += 1
        return n
