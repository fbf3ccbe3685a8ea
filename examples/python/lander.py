"""A lunar lander on minkowski, with the Gymnasium interface (after Gymnasium's LunarLander).

Land the craft on the pad between the flags. Observation (8 floats): position relative to
the pad (x, y), velocity (vx, vy), angle, angular velocity, and whether each leg touches the
ground. Actions (Discrete(4)): 0 nothing, 1 fire the left orientation engine, 2 the main
engine, 3 the right orientation engine; or with continuous=True a Box(-1, 1, (2,)): main
throttle (on above 0) and side throttle (left below -0.5, right above 0.5).

Reward: moving towards the pad, slowing down and staying level earn; each leg's contact earns
10; firing costs 0.3 (main) or 0.03 (side) a step. Crashing (the hull touches the ground) or
flying out of view ends the episode with -100, coming to rest with +100. An episode is
truncated after max_episode_steps.
"""

import math

import numpy

import minkowski
from minkowski.envs import WorldEnv, spaces

WIDTH, HEIGHT = 20.0, 13.333  # the view, metres
CHUNKS = 11
LEG_AWAY, LEG_DOWN = 0.67, 0.6
HULL = [(-0.47, 0.57), (-0.57, 0.0), (-0.57, -0.33), (0.57, -0.33), (0.57, 0.0), (0.47, 0.57)]
# Impulses per step at full throttle, per kilogram of hull: the main engine lifts about
# one and a half times the craft's weight.
MAIN_ENGINE_IMPULSE = 0.3
SIDE_ENGINE_IMPULSE = 0.03
GROUND, CRAFT = 0b01, 0b10


class LunarLander(WorldEnv):
    metadata = {"render_modes": ["rgb_array"], "render_fps": 50}

    def __init__(self, render_mode=None, continuous=False, max_episode_steps=400):
        super().__init__(render_mode)
        self.continuous = continuous
        self.max_episode_steps = max_episode_steps
        if continuous:
            self.action_space = spaces.Box(-1.0, 1.0, (2,), dtype=numpy.float32)
        else:
            self.action_space = spaces.Discrete(4)
        high = numpy.array([2.5, 2.5, 10, 10, 2 * math.pi, 10, 1, 1], dtype=numpy.float32)
        self.observation_space = spaces.Box(-high, high, dtype=numpy.float32)
        self.view = ((0.0, 0.0), (WIDTH, HEIGHT))

    # The world: terrain with a flat pad in the middle, the hull, two legs on sprung hinges.
    def _build(self):
        rng = self.np_random
        world = minkowski.World(gravity=(0, -10), time_step=1 / 50, substeps=4)
        heights = rng.uniform(0, HEIGHT / 2, size=CHUNKS + 1)
        self.pad_y = HEIGHT / 4
        middle = CHUNKS // 2
        heights[middle - 2:middle + 3] = self.pad_y
        xs = numpy.linspace(0, WIDTH, CHUNKS)
        smooth = [0.33 * (heights[i - 1] + heights[i] + heights[i + 1]) for i in range(CHUNKS)]
        self.pad_x = (xs[middle - 1], xs[middle + 1])
        ground = world.create_body("static")
        # Right to left, so that each segment's solid side faces up.
        points = [(x, y) for x, y in zip(xs, smooth)][::-1]
        ground.add_chain(points, friction=0.1, filter=minkowski.Filter(category=GROUND))
        for x in self.pad_x:  # flags: sensors, drawn but never touched
            ground.add_segment((x, self.pad_y), (x, self.pad_y + 1.0), sensor=True)
            ground.add_polygon([(x, self.pad_y + 1.0), (x, self.pad_y + 0.6),
                                (x + 0.5, self.pad_y + 0.8)], sensor=True)
        self.ground = ground

        craft = minkowski.Filter(category=CRAFT, mask=GROUND)
        start = (WIDTH / 2, HEIGHT)
        hull = world.create_body("dynamic", position=start)
        hull.add_polygon(HULL, density=5, friction=0.1, filter=craft)
        hull.apply_impulse(tuple(rng.uniform(-1, 1, size=2) * hull.mass * 1.5))
        self.hull = hull
        self.legs = []
        for side in (-1, 1):
            leg = world.create_body("dynamic", position=(start[0] - side * LEG_AWAY, start[1]),
                                    angle=side * 0.05)
            leg.add_box(0.067, 0.267, density=1, friction=0.2, filter=craft)
            limit = minkowski.JointLimit(0.4, 0.9) if side == -1 else minkowski.JointLimit(-0.9, -0.4)
            # The leg's top pins to the hull's centre; motor and limit splay it out and down.
            world.revolute_joint(hull, leg, local_anchor_b=(side * LEG_AWAY, LEG_DOWN),
                                 limit=limit, motor=minkowski.JointMotor(speed=0.3 * side,
                                                                         max_force=40))
            self.legs.append(leg)
        self.world = world
        self.leg_shapes = [leg.shapes[0].index for leg in self.legs]
        self.hull_shape = hull.shapes[0].index
        self.ground_shapes = {s.index for s in ground.shapes}

    def reset(self, *, seed=None, options=None):
        super().reset(seed=seed)
        self._build()
        self.touching = [False, False]
        self.crashed = False
        self.steps = 0
        self.previous_shaping = None
        self.world.step()
        return self._observe(), {}

    def _contacts(self):
        """Leg contacts and crashes from the step's contact events."""
        for events, touching in ((self.world.contact_begin_events(), True),
                                 (self.world.contact_end_events(), False)):
            for shape_a, shape_b in zip(events["shape_a"], events["shape_b"]):
                pair = {int(shape_a), int(shape_b)}
                if not pair & self.ground_shapes:
                    continue
                if self.hull_shape in pair and touching:
                    self.crashed = True
                for i, leg in enumerate(self.leg_shapes):
                    if leg in pair:
                        self.touching[i] = touching

    def _observe(self):
        (x, y, angle, vx, vy, w) = self.world.states([self.hull.index])[0]
        return numpy.array([
            (x - WIDTH / 2) / (WIDTH / 2),
            (y - (self.pad_y + LEG_DOWN)) / (HEIGHT / 2),
            vx * (WIDTH / 2) / 50,
            vy * (HEIGHT / 2) / 50,
            angle,
            20.0 * w / 50,
            float(self.touching[0]),
            float(self.touching[1]),
        ], dtype=numpy.float32)

    def _throttles(self, action):
        """(main, side) in [0, 1] and [-1, 1] from either kind of action."""
        if self.continuous:
            action = numpy.clip(numpy.asarray(action, dtype=float), -1, 1)
            main = (action[0] + 1) / 2 * 0.5 + 0.5 if action[0] > 0 else 0.0
            side = action[1] if abs(action[1]) > 0.5 else 0.0
            return main, side
        if not self.action_space.contains(action):
            raise minkowski.InvalidArgumentError(f"action {action!r} is not in {self.action_space}")
        return (1.0 if action == 2 else 0.0), {1: -1.0, 3: 1.0}.get(int(action), 0.0)

    def step(self, action):
        main, side = self._throttles(action)
        angle = self.hull.angle
        up = (-math.sin(angle), math.cos(angle))
        across = (math.cos(angle), math.sin(angle))
        dispersion = self.np_random.uniform(-1, 1, size=2) * 0.1
        mass = self.hull.mass
        centre = self.hull.world_center
        if main > 0:
            # The flame pushes the hull up from below its centre, a little off line.
            strength = MAIN_ENGINE_IMPULSE * mass * main
            direction = (up[0] + dispersion[0], up[1] + dispersion[1])
            self.hull.apply_impulse((direction[0] * strength, direction[1] * strength),
                                    (centre[0] - up[0] * 0.3, centre[1] - up[1] * 0.3))
        if side != 0:
            # A side engine high on the hull pushes it sideways there and so turns it: the
            # left one (side < 0) counter-clockwise, the right one clockwise.
            strength = SIDE_ENGINE_IMPULSE * mass * abs(side)
            sign = -1.0 if side < 0 else 1.0
            at = (centre[0] - sign * across[0] * 0.5 + up[0] * 0.3,
                  centre[1] - sign * across[1] * 0.5 + up[1] * 0.3)
            self.hull.apply_impulse((sign * across[0] * strength, sign * across[1] * strength), at)
        self.world.step()
        self.steps += 1
        self._contacts()
        state = self._observe()

        shaping = (-100 * math.hypot(state[0], state[1]) - 100 * math.hypot(state[2], state[3])
                   - 100 * abs(state[4]) + 10 * state[6] + 10 * state[7])
        reward = 0.0 if self.previous_shaping is None else shaping - self.previous_shaping
        self.previous_shaping = shaping
        reward -= main * 0.30 + abs(side) * 0.03

        terminated = False
        if self.crashed or abs(state[0]) >= 1.0 or self.hull.position[1] > 2 * HEIGHT:
            terminated, reward = True, -100.0
        elif not self.hull.awake:
            terminated, reward = True, 100.0
        truncated = not terminated and self.steps >= self.max_episode_steps
        return state, float(reward), terminated, truncated, {}
