'use strict';
// The book's page, run by tools/book_runner in a worker thread of its own: the page's
// heap has a limit there (a script that allocates for ever ends this thread alone, and
// the runner says so in one line), and the runner's main thread stays free to answer
// Ctrl-C or SIGTERM while the book's code runs. It loads the page, builds the scene,
// runs the frames and writes the dump, then posts one message: what it did, or why it
// stopped and with which exit status (tools/book_runner's header lists them).

const { parentPort, workerData } = require('worker_threads');
const { parseKeyScript } = require('./inputs.js');
const { Page, PageError, ProjectError } = require('./page.js');
const { StateDump, DumpShapeError } = require('./dump.js');
const { MersenneTwister64 } = require('./random.js');

// The book's names the runner relies on: the engine core's object list, gravity and
// movement flag, the physics' collision pass and correction flag, the shapes' classes.
function engineOf(page) {
    const engine = page.lookup('gEngine');
    const core = engine && engine.Core;
    const physics = engine && engine.Physics;
    if (!core || !Array.isArray(core.mAllObjects) || !physics || typeof physics.collision !== 'function') {
        throw new ProjectError('no gEngine.Core.mAllObjects and gEngine.Physics.collision after loading: ' +
            'the runner needs a book project from chapter 3 on');
    }
    return { core, physics };
}

// Our scene in place of the book's MyGame: the world's settings the book exposes, then
// each body built with the book's own constructor, turned with its rotate(), and set
// moving (docs/scene_format.md: the same order our stages build it in).
function sceneBuilder(page, scene) {
    return function MyGameFromScene() {
        const { core, physics } = engineOf(page);
        const [Vec2, Circle, Rectangle] = ['Vec2', 'Circle', 'Rectangle'].map((name) => page.lookup(name));
        if (scene.world.gravity) {
            core.mGravity.x = scene.world.gravity[0];
            core.mGravity.y = scene.world.gravity[1];
        }
        if (scene.world.movement !== undefined) core.mMovement = scene.world.movement;
        if (scene.world.positional_correction !== undefined) {
            physics.mPositionalCorrectionFlag = scene.world.positional_correction;
        }
        for (const body of scene.bodies) {
            const center = new Vec2(body.center[0], body.center[1]);
            const shape = body.shape === 'circle'
                ? new Circle(center, body.radius, body.mass, body.friction, body.restitution)
                : new Rectangle(center, body.width, body.height, body.mass, body.friction, body.restitution);
            shape.rotate(body.angle);
            shape.mVelocity = new Vec2(body.velocity[0], body.velocity[1]);
            shape.mAngularVelocity = body.angularVelocity;
        }
    };
}

// Each fixed update of the book's loop starts with the collision pass, so the state
// just before a pass (or at the end of a frame) is the state after the update before it.
function runAndDump(page, options, dump) {
    const { core, physics } = engineOf(page);
    const collision = physics.collision;
    let step = 0;
    let updateRunning = false;
    let failure;
    const finishUpdate = () => {
        if (!updateRunning) return;
        updateRunning = false;
        step += 1;
        dump.rows(step, core.mAllObjects);
    };
    // Called from inside the page, where a throw would pass for the page's own: a
    // failure to record is kept, and stops the run after the frame.
    physics.collision = function collisionThenRecord(...args) {
        try {
            finishUpdate();
        } catch (error) {
            failure = failure || error;
        }
        updateRunning = true;
        return collision.apply(this, args);
    };
    const presses = parseKeyScript(options.keys);
    for (let frame = 0; frame < options.frames; frame++) {
        page.advanceFrame();
        for (const code of presses.get(frame) || []) page.keyDown(code);
        page.animationFrame();
        if (failure) throw failure;
        finishUpdate();
    }
    return step;
}

function run(options) {
    let dump;
    try {
        dump = new StateDump(options.dump);
    } catch (error) {
        return { status: 1, message: `cannot write ${options.dump}: ${error.code || error.message}` };
    }
    let page;
    let steps;
    try {
        page = new Page(options.project, options.book, options.frameMs, new MersenneTwister64(options.seed),
            options.scriptTimeoutMs);
        if (options.scene) page.replace('MyGame', sceneBuilder(page, options.scene));
        page.load();
        dump.rows(0, engineOf(page).core.mAllObjects);
        steps = runAndDump(page, options, dump);
    } catch (error) {
        dump.abort();
        if (error && error.code && !(error instanceof PageError || error instanceof DumpShapeError)) {
            return { status: 1, message: `cannot write ${options.dump}: ${error.code}` };
        }
        if (!(error instanceof PageError || error instanceof DumpShapeError)) throw error;
        return { status: error instanceof ProjectError ? 2 : 3, message: error.message };
    }
    try {
        dump.finish();
    } catch (error) {
        return { status: 1, message: `cannot write ${options.dump}: ${error.code || error.message}` };
    }
    return { status: 0, steps, errors: page.errors, errorCount: page.errorCount };
}

parentPort.postMessage(run(workerData));
