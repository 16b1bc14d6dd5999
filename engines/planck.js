'use strict';
// planck.js (npm `planck`), the JavaScript rewrite of Box2D, as an outside solver: one dynamic
// body with one circle fixture per disk, a static chain loop on the walls, static bodies for
// stones. planck computes in JavaScript numbers (double). Presets and why: docs/engines.md.
const { main, meanRadius, requireEngine } = require('./protocol.js');

const planck = requireEngine('planck');

// Global settings of planck (planck.Settings), read before this adapter changes any.
const shipped = {
  velocity_threshold: planck.Settings.velocityThreshold,  // m/s: slower contacts do not bounce
  linear_slop: planck.Settings.linearSlop,                // m of overlap left alone
  velocity_iterations: 8, position_iterations: 3,         // planck's own defaults for step()
  sleeping: true, warm_starting: true, continuous: true,
  fixed_rotation: false,
  length_scale: 1,                                        // planck metres per scene unit
  wall_restitution_per_contact: false,                    // planck mixes restitution as max(a, b)
};
// Box2D's tuning for hard disks (box2d/box2d_options.h): every approaching contact bounces,
// disks of 0.5 m, no sleeping, no spin, the walls' restitution on wall contacts.
const tuned = { ...shipped, velocity_threshold: 0, sleeping: false, fixed_rotation: true,
  length_scale: 0, wall_restitution_per_contact: true };  // length_scale 0: mean radius -> 0.5 m

function create(request, disks, o) {
  planck.Settings.velocityThreshold = o.velocity_threshold;
  planck.Settings.linearSlop = o.linear_slop;
  const s = o.length_scale > 0 ? o.length_scale : 0.5 / meanRadius(disks);
  const cx = 0.5 * (request.xmin + request.xmax), cy = 0.5 * (request.ymin + request.ymax);
  const world = new planck.World({ gravity: planck.Vec2(s * request.gravity_x, s * request.gravity_y),
    allowSleep: o.sleeping, warmStarting: o.warm_starting, continuousPhysics: o.continuous });
  // A chain's skin (polygonRadius) moved outside, so the touching surface is the scene's wall.
  const skin = planck.Settings.polygonRadius;
  const x0 = s * (request.xmin - cx) - skin, x1 = s * (request.xmax - cx) + skin;
  const y0 = s * (request.ymin - cy) - skin, y1 = s * (request.ymax - cy) + skin;
  const walls = world.createBody().createFixture(
    planck.Chain([planck.Vec2(x0, y0), planck.Vec2(x0, y1), planck.Vec2(x1, y1), planck.Vec2(x1, y0)], true),
    { restitution: request.wall_restitution, friction: 0 });
  let contacts = 0;
  world.on('begin-contact', (contact) => {
    const wall = contact.getFixtureA() === walls || contact.getFixtureB() === walls;
    if (!wall) ++contacts;
    else if (o.wall_restitution_per_contact) contact.setRestitution(request.wall_restitution);
  });
  const bodies = disks.map((d) => {
    const body = world.createBody({ type: d.stone ? 'static' : 'dynamic', position: planck.Vec2(s * (d.x - cx), s * (d.y - cy)),
      linearVelocity: planck.Vec2(s * d.vx, s * d.vy), fixedRotation: o.fixed_rotation, allowSleep: o.sleeping,
      linearDamping: request.damping });
    const r = s * d.radius;
    body.createFixture(planck.Circle(r), { density: d.mass / (Math.PI * r * r), restitution: request.restitution,
      friction: request.friction });
    return body;
  });
  return {
    step: (h) => world.step(h, o.velocity_iterations, o.position_iterations),
    state: (i) => {
      const p = bodies[i].getPosition(), v = bodies[i].getLinearVelocity();
      return [p.x / s + cx, p.y / s + cy, v.x / s, v.y / s];
    },
    get contacts() { return contacts; },
  };
}

main({ name: 'planck', presets: { tuned, shipped }, create });
