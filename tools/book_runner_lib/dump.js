'use strict';
// The state dump our stages write with --dump (common/state_dump.h), written from the
// book's shapes: step,index,shape,cx,cy,angle,vx,vy,angular_velocity, one row per
// shape after every fixed update, step 0 as built. Numbers are printed as C++'s
// std::to_chars(general, 17) prints them (what %.17g prints), so that a dump of the
// same doubles is the same text in both.

const fs = require('fs');

const kHeader = 'step,index,shape,cx,cy,angle,vx,vy,angular_velocity';
const kDigits = 17;

// %.17g: scientific when the decimal exponent is below -4 or at least 17, fixed
// otherwise; trailing zeros dropped; an exponent of at least two digits.
function formatNumber(value) {
    if (Number.isNaN(value)) return 'nan';
    if (!Number.isFinite(value)) return value > 0 ? 'inf' : '-inf';
    if (value === 0) return Object.is(value, -0) ? '-0' : '0';
    const [mantissa, exponentText] = value.toExponential(kDigits - 1).split('e');
    const exponent = Number(exponentText);
    const trim = (text) => (text.includes('.') ? text.replace(/0+$/, '').replace(/\.$/, '') : text);
    if (exponent < -4 || exponent >= kDigits) {
        const sign = exponent < 0 ? '-' : '+';
        return `${trim(mantissa)}e${sign}${String(Math.abs(exponent)).padStart(2, '0')}`;
    }
    const negative = mantissa.startsWith('-');
    const digits = mantissa.replace('-', '').replace('.', '');
    let fixed;
    if (exponent >= 0) {
        fixed = `${digits.slice(0, exponent + 1)}.${digits.slice(exponent + 1)}`;
    } else {
        fixed = `0.${'0'.repeat(-exponent - 1)}${digits}`;
    }
    return (negative ? '-' : '') + trim(fixed);
}

// A shape a dump has no name for.
class DumpShapeError extends Error {}

// The shape's name in a dump, from the book's mType ("Rectangle", "Circle").
function shapeName(shape) {
    const type = String(shape && shape.mType).toLowerCase();
    if (type !== 'rectangle' && type !== 'circle') {
        throw new DumpShapeError(`the book's object list holds a shape of type ${JSON.stringify(shape && shape.mType)}, ` +
            'which a dump cannot name (rectangle or circle)');
    }
    return type;
}

// Rows go to "<path>.partial-<pid>" as the run goes (a buffer of about a megabyte at a
// time, so a long run needs no more memory than a short one); finish() renames it to
// <path>, so a run that fails never leaves a file that looks like a whole dump. The
// partial file is made new: one already there under that name is never written over.
const kFlushBytes = 1 << 20;

class StateDump {
    constructor(file) {
        this.file = file;
        this.partial = `${file}.partial-${process.pid}`;
        this.fd = fs.openSync(this.partial, 'wx');
        this.lines = [kHeader];
        this.bytes = kHeader.length;
    }

    rows(step, shapes) {
        shapes.forEach((shape, index) => {
            const numbers = [shape.mCenter.x, shape.mCenter.y, shape.mAngle, shape.mVelocity.x, shape.mVelocity.y,
                shape.mAngularVelocity];
            const line = [step, index, shapeName(shape), ...numbers.map(formatNumber)].join(',');
            this.lines.push(line);
            this.bytes += line.length + 1;
        });
        if (this.bytes >= kFlushBytes) this.flush();
    }

    flush() {
        if (this.lines.length === 0) return;
        fs.writeSync(this.fd, `${this.lines.join('\n')}\n`);
        this.lines = [];
        this.bytes = 0;
    }

    finish() {
        try {
            this.flush();
            fs.closeSync(this.fd);
            this.fd = undefined;
            fs.renameSync(this.partial, this.file);
        } catch (error) {
            this.abort();
            throw error;
        }
    }

    // The partial file removed: the run failed or was stopped.
    abort() {
        try {
            if (this.fd !== undefined) fs.closeSync(this.fd);
        } catch (ignored) {
            // already closed
        }
        this.fd = undefined;
        removePartial(this.file);
    }
}

// The partial file of this process's dump to `file`, removed if it is there.
function removePartial(file) {
    try {
        fs.unlinkSync(`${file}.partial-${process.pid}`);
    } catch (ignored) {
        // nothing was written
    }
}

module.exports = { StateDump, DumpShapeError, formatNumber, removePartial };
