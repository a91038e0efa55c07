'use strict';
// What the runner reads besides the book's code: one of our scene files
// (docs/scene_format.md) and one of our key scripts (common/keys.h), in the grammar our
// programs read. A malformed one is refused with one line naming the file or token and
// the problem. The ranges of the numbers are left to the book's code, which has none:
// run the scene through our stage first, which checks them.

const fs = require('fs');

class InputError extends Error {}

// The whole of a file the runner reads (a scene, index.html, a script), when it is a
// regular file of at most `mostBytes`: opened without blocking and checked once open, so
// that a FIFO is refused rather than waited on for ever, and a device such as /dev/zero
// rather than read without end. Throws `ErrorKind` with "<file>: <reason>".
function readRegularFile(file, mostBytes, ErrorKind) {
    let fd;
    try {
        fd = fs.openSync(file, fs.constants.O_RDONLY | fs.constants.O_NONBLOCK);
    } catch (error) {
        throw new ErrorKind(`${file}: cannot read it (${error.code || error.message})`);
    }
    try {
        const stat = fs.fstatSync(fd);
        if (stat.isDirectory()) throw new ErrorKind(`${file}: it is a folder, not a file`);
        if (stat.isFIFO()) throw new ErrorKind(`${file}: it is a FIFO, not a regular file`);
        if (stat.isCharacterDevice() || stat.isBlockDevice()) {
            throw new ErrorKind(`${file}: it is a device, not a regular file`);
        }
        if (!stat.isFile()) throw new ErrorKind(`${file}: it is not a regular file`);
        if (stat.size > mostBytes) throw new ErrorKind(`${file}: larger than ${mostBytes} bytes, the most it may be`);
        // One byte past the limit tells a file that grew while it was read.
        const buffer = Buffer.alloc(mostBytes + 1);
        let length = 0;
        for (;;) {
            const got = fs.readSync(fd, buffer, length, buffer.length - length, null);
            if (got === 0) break;
            length += got;
            if (length > mostBytes) throw new ErrorKind(`${file}: larger than ${mostBytes} bytes, the most it may be`);
        }
        return buffer.toString('utf8', 0, length);
    } catch (error) {
        if (error instanceof ErrorKind) throw error;
        throw new ErrorKind(`${file}: cannot read it (${error.code || error.message})`);
    } finally {
        fs.closeSync(fd);
    }
}

// The keys the book's UserControl.js listens for, by our script's names, with the key
// codes a browser's keydown event carries for them.
function keyCode(name) {
    if (/^[a-z]$/.test(name)) return name.toUpperCase().charCodeAt(0);
    if (/^[0-9]$/.test(name)) return name.charCodeAt(0);
    if (name === 'comma' || name === ',') return 188;
    if (name === 'up') return 38;
    if (name === 'down') return 40;
    return undefined;
}

// What a scene may hold (docs/scene_format.md, common/scene_file.h): our programs' limits.
const kMostSceneBytes = 2 * 1024 * 1024;
const kMostNesting = 4;

const kMaxCount = 2000;
const kMaxFrame = 10000000;
const kMaxPresses = 2000;

function wholeNumber(text, low, high) {
    if (!/^[0-9]+$/.test(text)) return undefined;
    const value = Number(text);
    return value >= low && value <= high ? value : undefined;
}

// The script KEY[*COUNT][@FRAME] ... as a map from frame to the key codes pressed
// before that frame, in script order; a token without @ keeps the frame of the token
// before it.
function parseKeyScript(script) {
    const presses = new Map();
    let frame = 0;
    let total = 0;
    for (const token of script.split(/\s+/).filter((t) => t.length > 0)) {
        const match = /^([^*@]+)(?:\*([^@]*))?(?:@(.*))?$/.exec(token);
        const refuse = (why) => {
            throw new InputError(`bad key script token "${token}": ${why} (keys: a-z, 0-9, comma, up, down)`);
        };
        if (!match) refuse('not KEY[*COUNT][@FRAME]');
        const code = keyCode(match[1].toLowerCase());
        if (code === undefined) refuse(`unknown key "${match[1]}"`);
        const count = match[2] === undefined ? 1 : wholeNumber(match[2], 1, kMaxCount);
        if (count === undefined) refuse(`the count must be a whole number from 1 to ${kMaxCount}`);
        if (match[3] !== undefined) {
            frame = wholeNumber(match[3], 0, kMaxFrame);
            if (frame === undefined) refuse(`the frame must be a whole number from 0 to ${kMaxFrame}`);
        }
        total += count;
        if (total > kMaxPresses) refuse(`more than ${kMaxPresses} key presses in all`);
        if (!presses.has(frame)) presses.set(frame, []);
        for (let i = 0; i < count; i++) presses.get(frame).push(code);
    }
    return presses;
}

// The world keys the book's code can be given, and how. The book keeps its loop's step,
// its canvas size and its relaxation numbers in private variables of Core.js and
// Physics.js, so those keys are taken only at the book's own values.
const kBookFixed = {
    width: 800,
    height: 450,
    dt: 1 / 60,
    relaxation_iterations: 15,
    correction_rate: 0.8,
    remove_out_of_bounds: true,
};
const kBookSettable = ['gravity', 'movement', 'positional_correction'];

const kBodyKeys = ['shape', 'center', 'width', 'height', 'radius', 'mass', 'friction', 'restitution', 'angle',
    'velocity', 'angular_velocity'];

function describe(value) {
    // JSON.parse reads a number beyond a double's range (1e400) as an infinity, which
    // JSON.stringify would show as null.
    if (typeof value === 'number' && !Number.isFinite(value)) return 'a number beyond the range of a double';
    const text = JSON.stringify(value);
    return text.length > 40 ? `${text.slice(0, 37)}...` : text;
}

// A scene: {world: {gravity?, movement?, positional_correction?}, bodies: [...]}, each
// body with every key filled in with its documented default.
function parseScene(file) {
    const text = readRegularFile(file, kMostSceneBytes, InputError);
    // {"bodies": [{"center": [x, y]}]} is as deep as a scene goes: deeper nesting is
    // refused before JSON.parse, whose recursion it would otherwise reach.
    let depth = 0;
    let inString = false;
    for (let i = 0; i < text.length; i++) {
        const c = text[i];
        if (inString) {
            if (c === '\\') i++;
            else if (c === '"') inString = false;
        } else if (c === '"') inString = true;
        else if (c === '{' || c === '[') {
            if (++depth > kMostNesting) {
                throw new InputError(`${file}: nested deeper than a scene can use (${kMostNesting} levels: ` +
                    '{"bodies": [{"center": [x, y]}]})');
            }
        } else if (c === '}' || c === ']') depth--;
    }
    let scene;
    try {
        scene = JSON.parse(text);
    } catch (error) {
        throw new InputError(`${file}: not JSON (${error.message.split('\n')[0]})`);
    }
    const refuse = (where, why) => {
        throw new InputError(`${file}: ${where}: ${why}`);
    };
    const isObject = (v) => typeof v === 'object' && v !== null && !Array.isArray(v);
    if (!isObject(scene)) refuse('(top)', 'a scene is a JSON object');
    for (const key of Object.keys(scene)) {
        if (key !== 'world' && key !== 'bodies') refuse(key, 'unknown key (a scene has "world" and "bodies")');
    }
    const number = (where, v) => {
        if (typeof v !== 'number' || !Number.isFinite(v)) refuse(where, `must be a finite number (got ${describe(v)})`);
        return v;
    };
    const pair = (where, v) => {
        if (!Array.isArray(v) || v.length !== 2) refuse(where, `must be [x, y] (got ${describe(v)})`);
        return [number(`${where}[0]`, v[0]), number(`${where}[1]`, v[1])];
    };
    const flag = (where, v) => {
        if (typeof v !== 'boolean') refuse(where, `must be true or false (got ${describe(v)})`);
        return v;
    };

    const world = {};
    const worldIn = scene.world === undefined ? {} : scene.world;
    if (!isObject(worldIn)) refuse('world', 'must be an object');
    for (const [key, value] of Object.entries(worldIn)) {
        const where = `world.${key}`;
        if (key in kBookFixed) {
            const ok = typeof value === typeof kBookFixed[key] && value === kBookFixed[key];
            if (!ok) {
                refuse(where, `the book's code keeps this in a private variable, so only its own value ` +
                    `${describe(kBookFixed[key])} can run (got ${describe(value)})`);
            }
        } else if (key === 'gravity') {
            world.gravity = pair(where, value);
        } else if (key === 'movement' || key === 'positional_correction') {
            world[key] = flag(where, value);
        } else {
            refuse(where, `the book's code has no such setting (it takes ${[...kBookSettable,
                ...Object.keys(kBookFixed)].join(', ')})`);
        }
    }

    if (!Array.isArray(scene.bodies)) refuse('bodies', 'must be a list of bodies');
    if (scene.bodies.length > 2500) refuse('bodies', 'at most 2500 bodies');
    const bodies = scene.bodies.map((body, i) => {
        const where = (key) => `bodies[${i}].${key}`;
        if (!isObject(body)) refuse(`bodies[${i}]`, 'must be an object');
        for (const key of Object.keys(body)) {
            if (!kBodyKeys.includes(key)) refuse(where(key), 'unknown key');
        }
        if (body.shape !== 'rectangle' && body.shape !== 'circle') {
            refuse(where('shape'), `must be "rectangle" or "circle" (got ${describe(body.shape)})`);
        }
        const positive = (key) => {
            const v = number(where(key), body[key]);
            if (v <= 0) refuse(where(key), `must be > 0 (got ${v})`);
            return v;
        };
        const optional = (key, fallback, read) => (body[key] === undefined ? fallback : read(where(key), body[key]));
        const made = {
            shape: body.shape,
            center: pair(where('center'), body.center),
            mass: optional('mass', 1, number),
            friction: optional('friction', 0.8, number),
            restitution: optional('restitution', 0.2, number),
            angle: optional('angle', 0, number),
            velocity: optional('velocity', [0, 0], pair),
            angularVelocity: optional('angular_velocity', 0, number),
        };
        if (made.mass < 0) refuse(where('mass'), 'must be >= 0');
        const foreign = body.shape === 'circle' ? ['width', 'height'] : ['radius'];
        for (const key of foreign) {
            if (key in body) refuse(where(key), `a ${body.shape} has no ${key}`);
        }
        if (body.shape === 'circle') {
            made.radius = positive('radius');
        } else {
            made.width = positive('width');
            made.height = positive('height');
        }
        return made;
    });
    return { world, bodies };
}

module.exports = { InputError, parseKeyScript, parseScene, readRegularFile };
