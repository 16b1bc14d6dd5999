'use strict';
// matter.js (npm `matter-js`) as an outside solver: one circle body per disk (a regular polygon
// of up to `circle_sides` sides: matter.js has no true circles), four static rectangles outside
// the walls, static circles for stones. matter.js computes in JavaScript numbers (double) with
// position Verlet in milliseconds and pixel-like units. Presets and why: docs/engines.md.
const { main, meanRadius, requireEngine } = require('./protocol.js');

const Matter = requireEngine('matter');

const { Bodies, Body, Composite, Engine, Events, Resolver } = Matter;
const baseDelta = Body._baseDelta;  // ms: matter.js states velocities per 1/60 s

const shipped = {
  resting_threshold: Resolver._restingThresh,  // normal speed (per base step) below which a contact does not bounce
  position_iterations: 6, velocity_iterations: 4,  // Engine.create's defaults
  circle_sides: 25,          // Bodies.circle's default maxSides (and never more sides than the radius in units)
  slop: 0.05,                // Body's default allowed overlap, in matter.js units
  fixed_rotation: false,
  length_scale: 1,           // matter.js units per scene unit
};
// Every approaching contact bounces; circles of 64 sides (so the radius must be 64 units or
// more: the mean radius becomes 100); no spin.
const tuned = { ...shipped, resting_threshold: 0, circle_sides: 64, fixed_rotation: true, length_scale: 0 };

function create(request, disks, o) {
  Resolver._restingThresh = o.resting_threshold;
  const s = o.length_scale > 0 ? o.length_scale : 100 / meanRadius(disks);
  const engine = Engine.create({ positionIterations: o.position_iterations, velocityIterations: o.velocity_iterations,
    gravity: { x: s * request.gravity_x, y: s * request.gravity_y, scale: 1e-6 } });  // units per ms^2
  const x0 = s * request.xmin, x1 = s * request.xmax, y0 = s * request.ymin, y1 = s * request.ymax;
  const thick = Math.max(x1 - x0, y1 - y0);
  const wallOptions = { isStatic: true, restitution: request.wall_restitution, friction: 0, frictionStatic: 0, slop: o.slop };
  const walls = [
    Bodies.rectangle(x0 - thick / 2, (y0 + y1) / 2, thick, 3 * thick, wallOptions),
    Bodies.rectangle(x1 + thick / 2, (y0 + y1) / 2, thick, 3 * thick, wallOptions),
    Bodies.rectangle((x0 + x1) / 2, y0 - thick / 2, 3 * thick, thick, wallOptions),
    Bodies.rectangle((x0 + x1) / 2, y1 + thick / 2, 3 * thick, thick, wallOptions)];
  // frictionAir f takes v <- v (1 - f h / base step): f = c base step, first order in the scene's damping c.
  const frictionAir = request.damping * baseDelta / 1000;
  const h = request.dt / (request.substeps || 1) * 1000;  // ms
  const bodies = disks.map((d) => {
    const body = Bodies.circle(s * d.x, s * d.y, s * d.radius, { restitution: request.restitution, friction: request.friction,
      frictionAir, slop: o.slop, isStatic: d.stone }, o.circle_sides);
    if (d.stone) return body;
    Body.setMass(body, d.mass);
    if (o.fixed_rotation) Body.setInertia(body, Infinity);
    body.deltaTime = h;  // setVelocity states the velocity per step of this length
    Body.setVelocity(body, { x: s * d.vx * baseDelta / 1000, y: s * d.vy * baseDelta / 1000 });
    return body;
  });
  Composite.add(engine.world, [...walls, ...bodies]);
  const wallSet = new Set(walls);
  let contacts = 0;
  Events.on(engine, 'collisionStart', (event) => {
    for (const pair of event.pairs) if (!wallSet.has(pair.bodyA) && !wallSet.has(pair.bodyB)) ++contacts;
  });
  return {
    step: (hs) => Engine.update(engine, hs * 1000),
    state: (i) => {
      const v = Body.getVelocity(bodies[i]);
      return [bodies[i].position.x / s, bodies[i].position.y / s, v.x * 1000 / baseDelta / s, v.y * 1000 / baseDelta / s];
    },
    get contacts() { return contacts; },
  };
}

main({ name: 'matter', presets: { tuned, shipped }, create });
