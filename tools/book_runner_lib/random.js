'use strict';
// The stand-in for Math.random() that our stage programs use (common/random.h): the
// 64-bit Mersenne Twister of C++'s std::mt19937_64, seeded the same way, and its top 53
// bits as a double in [0, 1). With the same --seed, the book's F, G and H keys then draw
// the very numbers ours draw, in the same order.
//
// The generator's constants are those of the C++ standard ([rand.predef]); BigInt keeps
// its 64-bit words exact, which a JavaScript number (53 bits) cannot.

const kWords = 312n;
const kShift = 156;
const kMask64 = (1n << 64n) - 1n;
const kUpperBits = 0xffffffff80000000n;
const kLowerBits = 0x7fffffffn;
const kTwist = 0xb5026f5aa96619e9n;
const kSeedMultiplier = 6364136223846793005n;

class MersenneTwister64 {
    constructor(seed) {
        this.state = new Array(Number(kWords));
        this.state[0] = BigInt.asUintN(64, BigInt(seed));
        for (let i = 1n; i < kWords; i++) {
            const previous = this.state[Number(i) - 1];
            this.state[Number(i)] = (kSeedMultiplier * (previous ^ (previous >> 62n)) + i) & kMask64;
        }
        this.next = Number(kWords);
    }

    // Refills the whole state at once, as the standard's algorithm does every 312 outputs.
    twist() {
        const n = this.state.length;
        for (let i = 0; i < n; i++) {
            const mixed = (this.state[i] & kUpperBits) | (this.state[(i + 1) % n] & kLowerBits);
            let shifted = mixed >> 1n;
            if (mixed & 1n) shifted ^= kTwist;
            this.state[i] = this.state[(i + kShift) % n] ^ shifted;
        }
        this.next = 0;
    }

    // The next 64-bit output, tempered.
    nextWord() {
        if (this.next >= this.state.length) this.twist();
        let y = this.state[this.next++];
        y ^= (y >> 29n) & 0x5555555555555555n;
        y ^= (y << 17n) & 0x71d67fffeda60000n;
        y ^= (y << 37n) & 0xfff7eee000000000n;
        y ^= y >> 43n;
        return y & kMask64;
    }

    // Like Math.random(): 53 random bits, uniform in [0, 1).
    nextDouble() {
        return Number(this.nextWord() >> 11n) * 2 ** -53;
    }
}

module.exports = { MersenneTwister64, kDefaultSeed: 2017 };
