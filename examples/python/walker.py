"""A two-legged walker on minkowski, with the Gymnasium interface (after Gymnasium's
BipedalWalker).

Walk right over rough ground as far as the terrain goes. Actions: Box(-1, 1, (4,)), the motor
torque (as a share of the most, signed) of the hips and knees. Observation (24 floats): the
hull's angle, angular velocity and velocity; each leg's hip angle and speed, knee angle and
speed and ground contact; and 10 lidar fractions (1: nothing within range), swept below and
ahead of the hull.

Reward: 130/30 per metre of progress (the original's scale), less 5 per radian of tilt
and a little per unit of torque. The episode ends with -100 when the hull touches the ground or
the walker falls off the left end, and truncates after max_episode_steps.
"""

import math

import numpy

import minkowski
from minkowski.envs import WorldEnv, spaces

FPS = 50
SCALE = 30.0  # the original's pixels per metre, kept in its reward and observation scales
VIEW_WIDTH, VIEW_HEIGHT = 600 / SCALE, 400 / SCALE
TERRAIN_STEP = 14 / SCALE
TERRAIN_LENGTH = 200
TERRAIN_HEIGHT = VIEW_HEIGHT / 4
TERRAIN_STARTPAD = 20
HULL = [(-30, 9), (6, 9), (34, 1), (34, -8), (-30, -8)]
LEG_DOWN = -8 / SCALE
LEG_W, LEG_H = 8 / SCALE, 34 / SCALE
SPEED_HIP, SPEED_KNEE = 4.0, 6.0
MOTORS_TORQUE = 80.0
LIDAR_RANGE = 160 / SCALE
GROUND, WALKER, LIDAR = 0b001, 0b010, 0b100


class BipedalWalker(WorldEnv):
    metadata = {"render_modes": ["rgb_array"], "render_fps": FPS}

    def __init__(self, render_mode=None, max_episode_steps=1600):
        super().__init__(render_mode)
        self.max_episode_steps = max_episode_steps
        self.action_space = spaces.Box(-1.0, 1.0, (4,), dtype=numpy.float32)
        self.observation_space = spaces.Box(-numpy.inf, numpy.inf, (24,), dtype=numpy.float32)
        self.lidar_probe = minkowski.ShapeDef.circle(0.01)
        self.lidar_filter = minkowski.Filter(category=LIDAR, mask=GROUND)

    def _terrain(self):
        """Grassy ground: a flat start, then a smoothed random walk."""
        rng = self.np_random
        y, velocity = TERRAIN_HEIGHT, 0.0
        points = []
        for i in range(TERRAIN_LENGTH):
            x = i * TERRAIN_STEP
            velocity = 0.8 * velocity + 0.01 * math.copysign(1, TERRAIN_HEIGHT - y)
            if i > TERRAIN_STARTPAD:
                velocity += rng.uniform(-1, 1) / SCALE
            y += velocity
            points.append((x, y if i > TERRAIN_STARTPAD else TERRAIN_HEIGHT))
        return points

    def _build(self):
        world = minkowski.World(gravity=(0, -10), time_step=1 / FPS, substeps=4)
        points = self._terrain()
        self.terrain_end = points[-1][0] - TERRAIN_STEP * 2
        ground = world.create_body("static")
        # Right to left: each segment's solid side faces up.
        ground.add_chain(points[::-1], friction=0.8, filter=minkowski.Filter(category=GROUND))
        part = minkowski.Filter(category=WALKER, mask=GROUND)
        x0 = TERRAIN_STEP * TERRAIN_STARTPAD / 2
        y0 = TERRAIN_HEIGHT + 2 * LEG_H
        hull = world.create_body("dynamic", position=(x0, y0))
        hull.add_polygon([(x / SCALE, y / SCALE) for x, y in HULL], density=5, friction=0.1,
                         filter=part)
        hull.apply_impulse((self.np_random.uniform(-5, 5) * hull.mass / 20, 0))
        self.hull = hull
        self.joints = []
        self.lower_legs = []
        for side in (-1, 1):
            upper = world.create_body("dynamic", position=(x0, y0 + LEG_DOWN - LEG_H / 2),
                                      angle=side * 0.05)
            upper.add_box(LEG_W / 2, LEG_H / 2, density=1, filter=part)
            lower = world.create_body("dynamic", position=(x0, y0 + LEG_DOWN - LEG_H * 3 / 2),
                                      angle=side * 0.05)
            lower.add_box(0.8 * LEG_W / 2, LEG_H / 2, density=1, filter=part)
            hip = world.revolute_joint(hull, upper, anchor=(x0, y0 + LEG_DOWN),
                                       limit=minkowski.JointLimit(-0.8, 1.1),
                                       motor=minkowski.JointMotor(0, MOTORS_TORQUE))
            knee = world.revolute_joint(upper, lower, anchor=(x0, y0 + LEG_DOWN - LEG_H),
                                        limit=minkowski.JointLimit(-1.6, -0.1),
                                        motor=minkowski.JointMotor(0, MOTORS_TORQUE))
            self.joints += [hip, knee]
            self.lower_legs.append(lower)
        self.world = world
        self.ground_shapes = {s.index for s in ground.shapes}
        self.hull_shape = hull.shapes[0].index
        self.leg_shapes = [leg.shapes[0].index for leg in self.lower_legs]

    def reset(self, *, seed=None, options=None):
        super().reset(seed=seed)
        self._build()
        self.contacts = [set(), set()]
        self.game_over = False
        self.steps = 0
        self.previous_shaping = None
        return self.step(numpy.zeros(4))[0], {}

    def _read_contacts(self):
        for events, touching in ((self.world.contact_begin_events(), True),
                                 (self.world.contact_end_events(), False)):
            for shape_a, shape_b in zip(events["shape_a"], events["shape_b"]):
                pair = {int(shape_a), int(shape_b)}
                ground = pair & self.ground_shapes
                if not ground:
                    continue
                if self.hull_shape in pair and touching:
                    self.game_over = True
                for i, leg in enumerate(self.leg_shapes):
                    if leg in pair:
                        (self.contacts[i].update if touching else
                         self.contacts[i].difference_update)(ground)

    def _lidar(self):
        origin = self.hull.position
        out = []
        for i in range(10):
            angle = 1.5 * i / 10.0
            ray = (math.sin(angle) * LIDAR_RANGE, -math.cos(angle) * LIDAR_RANGE)
            hit = self.world.cast_shape(self.lidar_probe, ray, position=origin,
                                        filter=self.lidar_filter)
            out.append(1.0 if hit is None else hit.fraction)
        return out

    def step(self, action):
        action = numpy.clip(numpy.asarray(action, dtype=float), -1, 1)
        if action.shape != (4,) or not numpy.all(numpy.isfinite(action)):
            raise minkowski.InvalidArgumentError(f"action {action!r} is not 4 finite numbers")
        for joint, value, speed in zip(self.joints, action, (SPEED_HIP, SPEED_KNEE) * 2):
            joint.motor = minkowski.JointMotor(speed * math.copysign(1, value),
                                               MOTORS_TORQUE * abs(value))
        self.world.step()
        self.steps += 1
        self._read_contacts()

        (x, _, angle, vx, vy, spin) = self.world.states([self.hull.index])[0]
        hip_a, knee_a, hip_b, knee_b = self.joints
        state = [angle, 2.0 * spin / FPS, 0.3 * vx * VIEW_WIDTH / FPS, 0.3 * vy * VIEW_HEIGHT / FPS]
        for hip, knee, contact in ((hip_a, knee_a, self.contacts[0]),
                                   (hip_b, knee_b, self.contacts[1])):
            state += [hip.coordinate, hip.speed / SPEED_HIP, knee.coordinate + 1.0,
                      knee.speed / SPEED_KNEE, 1.0 if contact else 0.0]
        state += self._lidar()
        observation = numpy.array(state, dtype=numpy.float32)

        shaping = 130 * x / SCALE - 5.0 * abs(angle)
        reward = 0.0 if self.previous_shaping is None else shaping - self.previous_shaping
        self.previous_shaping = shaping
        reward -= 0.00035 * MOTORS_TORQUE * float(numpy.sum(numpy.abs(action)))
        terminated = False
        if self.game_over or x < 0:
            terminated, reward = True, -100.0
        elif x > self.terrain_end:
            terminated = True
        truncated = not terminated and self.steps >= self.max_episode_steps
        # The camera follows the hull.
        self.view = ((x - VIEW_WIDTH / 4, 0.0), (x + VIEW_WIDTH * 3 / 4, VIEW_HEIGHT))
        return observation, float(reward), terminated, truncated, {}
