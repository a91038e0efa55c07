'use strict';
// A browser page as small as the book's projects need, so that their own JavaScript can
// run under Node without a screen: a document whose elements take whatever the scripts
// write into them, a canvas whose 2D context accepts every drawing call and draws
// nothing, requestAnimationFrame run by hand, and Date.now() read from a simulated
// clock, as our programs' clock (common/clock.h): the time after k frames is k times
// the frame length, so the book's loop runs the same fixed updates ours does.
//
// The page is loaded as a browser loads index.html: each <script src> in document
// order, in one shared global scope; then the body's onload code; key presses go to
// the body's onkeydown code as keydown events.

const fs = require('fs');
const path = require('path');
const vm = require('vm');
const { readRegularFile } = require('./inputs.js');

class PageError extends Error {}
// The folder given is no book project the runner can load: a refused argument.
class ProjectError extends PageError {}


// Any property read gives a function that does nothing, unless a script stored a value
// there first (strokeStyle, lineWidth, font...): every drawing call of any project works.
function drawingContext() {
    const stored = {};
    return new Proxy(stored, {
        get(target, name) {
            if (name in target) return target[name];
            return () => undefined;
        },
        set(target, name, value) {
            target[name] = value;
            return true;
        },
    });
}

function element(id) {
    const context = drawingContext();
    return { id, innerHTML: '', width: 300, height: 150, style: {}, getContext: () => context };
}

// The most the runner reads of a project: the book's index.html files are a few
// hundred bytes, its scripts a few kilobytes each.
const kMostIndexBytes = 1024 * 1024;
const kMostScriptBytes = 8 * 1024 * 1024;

// Whether `file`, its links resolved, lies inside the folder `root`.
function isInside(file, root) {
    const real = (name) => {
        try {
            return fs.realpathSync(name);
        } catch (error) {
            return path.resolve(name);
        }
    };
    const top = real(root);
    const found = real(file);
    return found === top || found.startsWith(top + path.sep);
}

// What index.html asks for: the scripts in order, and the body's two handlers.
function readIndex(folder) {
    const index = path.join(folder, 'index.html');
    if (!fs.existsSync(index)) {
        throw new ProjectError(`${folder}: no index.html to load (ENOENT); ` +
            'give the folder of one book project, the one that holds its index.html');
    }
    const html = readRegularFile(index, kMostIndexBytes, ProjectError);
    const scripts = [...html.matchAll(/<script\b[^>]*\bsrc\s*=\s*"([^"]+)"/gi)].map((m) => m[1]);
    const body = /<body\b([^>]*)>/i.exec(html);
    const handler = (name) => {
        const found = body && new RegExp(`\\b${name}\\s*=\\s*"([^"]*)"`, 'i').exec(body[1]);
        return found ? found[1] : '';
    };
    if (scripts.length === 0) throw new ProjectError(`${index}: loads no <script src="...">`);
    return { index, scripts, onload: handler('onload'), onkeydown: handler('onkeydown') };
}

class Page {
    // `folder` holds the project's index.html, inside `root`, the folder the reader gave,
    // out of which no script is read; `frameMs` is the length of one frame;
    // `random` stands in for Math.random(). A browser would hang on a script that never
    // returns; the page stops the run when one call of its code runs longer than
    // `longestCallMs` (a frame of 2,500 shapes takes a few seconds).
    constructor(folder, root, frameMs, random, longestCallMs) {
        this.frameMs = frameMs;
        this.longestCallMs = longestCallMs;
        this.frames = 0;
        this.callbacks = [];
        this.errors = [];  // the first few messages of throws in frames and key handlers
        this.errorCount = 0;
        const page = readIndex(folder);
        this.indexFile = page.index;

        const elements = new Map();
        const document = {
            getElementById: (id) => {
                if (!elements.has(id)) elements.set(id, element(id));
                return elements.get(id);
            },
        };
        const globals = {
            document,
            console,
            requestAnimationFrame: (callback) => this.callbacks.push(callback),
        };
        this.global = vm.createContext(globals);
        vm.runInContext('var window = this;', this.global);
        // The page's own Math and Date take the stand-ins, so nothing outside it changes.
        vm.runInContext('Math', this.global).random = () => random.nextDouble();
        vm.runInContext('Date', this.global).now = () => this.nowMs();

        for (const src of page.scripts) {
            const file = path.join(folder, src);
            if (!isInside(file, root)) {
                throw new ProjectError(`${page.index}: its script ${src} lies outside the project folder ${root}, ` +
                    'which is all the runner reads');
            }
            let code;
            try {
                code = readRegularFile(file, kMostScriptBytes, ProjectError);
            } catch (error) {
                throw new ProjectError(`${page.index}: cannot read its script ${src}: ${error.message}`);
            }
            this.run(() => vm.runInContext(code, this.global, { filename: file, timeout: this.longestCallMs }),
                `loading ${src}`);
        }
        this.onload = this.handler(page.onload, 'onload');
        this.onkeydown = this.handler(page.onkeydown, 'onkeydown');
    }

    // A global of the page's scripts by name: a `var` or function, or a `let`, `const`
    // or `class`, which a browser keeps outside the window object.
    lookup(name) {
        return vm.runInContext(`typeof ${name} === 'undefined' ? undefined : ${name}`, this.global);
    }

    // Puts `value` in place of the page's global `name`, whichever way it was declared.
    replace(name, value) {
        this.global.bookRunnerValue = value;
        vm.runInContext(`${name} = bookRunnerValue; delete globalThis.bookRunnerValue;`, this.global);
    }

    nowMs() {
        return this.frames * this.frameMs;
    }

    // The body's handler attribute as a function of `event`, as a browser compiles it.
    handler(code, name) {
        return this.run(() => vm.runInContext(`(function (event) {\n${code}\n})`, this.global,
            { filename: `${this.indexFile} (body ${name})` }), `reading the body's ${name}`);
    }

    // Runs the page's own code; what it throws while loading stops the run.
    run(action, what) {
        try {
            return action();
        } catch (error) {
            throw new PageError(`the book's code failed while ${what}: ${firstLine(error)}`);
        }
    }

    // Calls one of the page's functions from inside the page, so that the time limit
    // holds for everything it calls in turn.
    callInPage(action) {
        this.global.bookRunnerCall = action;
        try {
            return vm.runInContext('bookRunnerCall()', this.global, { timeout: this.longestCallMs });
        } finally {
            delete this.global.bookRunnerCall;
        }
    }

    // A throw in a handler or a frame does not stop a browser: it reports it and goes
    // on with the next event. So does the page here, keeping each message. A call that
    // never returns stops the run.
    dispatch(action, when) {
        try {
            this.callInPage(action);
        } catch (error) {
            if (error && error.code === 'ERR_SCRIPT_EXECUTION_TIMEOUT') {
                throw new PageError(`the book's code ran for over ${this.longestCallMs / 1000} s in ${when} ` +
                    'without returning (a loop that never ends?)');
            }
            this.errorCount += 1;
            if (this.errors.length < 10) this.errors.push(`${when}: ${firstLine(error)}`);
        }
    }

    load() {
        this.run(() => this.callInPage(() => this.onload.call(this.global, { type: 'load' })),
            'running the body\'s onload');
    }

    // A keydown as old and new browsers give it: window.event during the handler, and
    // the key code as both keyCode and which.
    keyDown(code) {
        const event = { type: 'keydown', keyCode: code, which: code };
        this.global.event = event;
        this.dispatch(() => this.onkeydown.call(this.global, event), `frame ${this.frames - 1}, key code ${code}`);
        delete this.global.event;
    }

    // The clock moves on by one frame (before the frame's keys, as in our programs).
    advanceFrame() {
        this.frames += 1;
    }

    // One animation frame: every callback requested before it.
    animationFrame() {
        const due = this.callbacks;
        this.callbacks = [];
        for (const callback of due) this.dispatch(() => callback(this.nowMs()), `frame ${this.frames - 1}`);
    }
}

function firstLine(error) {
    const text = error && error.stack ? String(error.stack) : String(error);
    const lines = text.split('\n');
    const where = lines.find((line) => /^\s+at /.test(line));
    return where ? `${lines[0]} (${where.trim().replace(/^at /, '')})` : lines[0];
}

module.exports = { Page, PageError, ProjectError };
