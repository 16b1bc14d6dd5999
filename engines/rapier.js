'use strict';
// Rapier (npm `@dimforge/rapier2d-compat`, Rust compiled to WebAssembly) as an outside solver:
// one dynamic rigid body with one ball collider per disk, four fixed cuboids outside the walls,
// fixed balls for stones. Rapier computes in f32 (precision float), so positions are taken
// relative to the box's centre, where floats are finest. Presets and why: docs/engines.md.
const { main, meanRadius, requireEngine } = require('./protocol.js');

const RAPIER = requireEngine('rapier');

const shipped = {
  solver_iterations: 4,        // IntegrationParameters' numSolverIterations default
  length_unit: 1,              // Rapier's tolerances (allowed overlap 0.001, prediction 0.02) are in these
  sleeping: true,              // RigidBodyDesc's canSleep default
  fixed_rotation: false,
  wall_combine: 'average',     // ColliderDesc's restitution combine rule: (e_disk + e_wall) / 2 at walls
};
// Twice the iterations, tolerances relative to a disk's diameter, no sleeping, no spin, and the
// wall's restitution on wall contacts (its rule wins: Min below the disks' e, Max above it).
const tuned = { ...shipped, solver_iterations: 8, length_unit: 0, sleeping: false, fixed_rotation: true, wall_combine: 'wall' };

function wallRule(o, request) {
  const rules = RAPIER.CoefficientCombineRule;
  if (o.wall_combine === 'average') return rules.Average;
  if (o.wall_combine !== 'wall') throw new Error(`option wall_combine = '${o.wall_combine}': expected average or wall`);
  return request.wall_restitution <= request.restitution ? rules.Min : rules.Max;
}

function create(request, disks, o) {
  const cx = 0.5 * (request.xmin + request.xmax), cy = 0.5 * (request.ymin + request.ymax);
  const world = new RAPIER.World({ x: request.gravity_x, y: request.gravity_y });
  world.integrationParameters.numSolverIterations = o.solver_iterations;
  world.integrationParameters.lengthUnit = o.length_unit > 0 ? o.length_unit : 2 * meanRadius(disks);
  const hx = 0.5 * (request.xmax - request.xmin), hy = 0.5 * (request.ymax - request.ymin), t = Math.max(hx, hy);
  const fixed = world.createRigidBody(RAPIER.RigidBodyDesc.fixed());
  const walls = new Set();
  for (const [x, y, w, h] of [[-hx - t, 0, t, 3 * t], [hx + t, 0, t, 3 * t], [0, -hy - t, 3 * t, t], [0, hy + t, 3 * t, t]]) {
    const desc = RAPIER.ColliderDesc.cuboid(w, h).setTranslation(x, y).setRestitution(request.wall_restitution).setFriction(0)
      .setRestitutionCombineRule(wallRule(o, request));
    walls.add(world.createCollider(desc, fixed).handle);
  }
  const bodies = disks.map((d) => {
    const desc = d.stone ? RAPIER.RigidBodyDesc.fixed() : RAPIER.RigidBodyDesc.dynamic().setLinvel(d.vx, d.vy)
      .setCanSleep(o.sleeping).setLinearDamping(request.damping);
    if (o.fixed_rotation && !d.stone) desc.lockRotations();
    const body = world.createRigidBody(desc.setTranslation(d.x - cx, d.y - cy));
    world.createCollider(RAPIER.ColliderDesc.ball(d.radius).setMass(d.mass).setRestitution(request.restitution)
      .setFriction(request.friction).setActiveEvents(RAPIER.ActiveEvents.COLLISION_EVENTS), body);
    return body;
  });
  const events = new RAPIER.EventQueue(true);
  let contacts = 0;
  return {
    step: (h) => {
      world.timestep = h;
      world.step(events);
      events.drainCollisionEvents((a, b, started) => { if (started && !walls.has(a) && !walls.has(b)) ++contacts; });
    },
    state: (i) => {
      const p = bodies[i].translation(), v = bodies[i].linvel();
      return [p.x + cx, p.y + cy, v.x, v.y];
    },
    get contacts() { return contacts; },
    free: () => { events.free(); world.free(); },  // wasm memory: a long-lived adapter serves many worlds
  };
}

main({ name: 'rapier', presets: { tuned, shipped },
  init: () => RAPIER.init(), create });
