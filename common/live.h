#pragma once
// The page played live: the same page a run saves as pictures, in a window, with the
// stage's keys from the keyboard.
//
// A live session is the same computation as a replay. The book's loop asks the real
// clock how much time has passed and runs as many fixed updates as fit (the book's frame
// skipping); here every frame shown moves the simulated clock on by exactly frame_ms,
// however long it really took, so a session and the replay of its key script run the
// same frames, the same updates and the same presses before the same frames. The window
// shows a frame at each refresh of the display, but never sooner than frame_ms of real
// time after the one before, so what moves on screen moves at the simulated speed while
// the machine keeps up, and slows down (rather than skipping) when it does not.
//
// Frames. Frame 0 runs and shows as the window opens. At each later refresh the keys
// pressed since the one before are pressed before the next frame, in order, then it
// runs and shows. A key pressed before frame k is recorded as KEY@k, so a session that
// showed frames 0 to n-1 replays with `--keys SCRIPT --frames n`, and the replay's
// final.png is the last page the window showed. The printed replay command adds
// `--from F`, F the frame of the first key press: the frames before it still run (the
// world moved while the reader looked on, and the replay must compute the same), but
// its pictures and GIF start there, with what the reader did, not the wait before it.
// Space pauses: no frame runs, the
// simulated clock stands still, and keys pressed meanwhile wait for the next frame that
// runs. Period runs one frame while paused. Pausing is not recorded, since it changes
// nothing a replay computes. Escape or closing the window ends the session; keys still
// waiting then were never pressed on the page, and are not recorded either. F12 saves
// the page shown (without the status line) in the current folder as
// <stage id>_frame_NNNN.png, NNNN the frame shown: the replay's frame_NNNN.png of the
// same frame is the same picture.
//
// The pointer. A press on the canvas (the left mouse button) starts a drag, which the
// page gets as pointer events (pointer.h) at whole canvas px: the press before the next
// frame that runs, then before each frame after it a move wherever the pointer is then
// (nothing where it stayed), and the release before the frame after the one the button
// came up in time for (a press and a release between two frames make a one-frame drag).
// A move outside the canvas is held at its edge; a press outside it does nothing. The
// drag is recorded as one token ("drag:412,203/420,205*3@40", keys.h), which the replay
// turns into the same events before the same frames; a drag still held when the
// session ends is recorded up to its last frame.
//
// Under the page the window shows one status line (the frame, whether it is paused,
// the keys waiting, the live keys); the page above it is the saved picture, pixel for
// pixel (page.h's with_status_line).

#include <vector>

#include "command_line.h"
#include "image.h"
#include "keys.h"
#include "page_scripts.h"

namespace browser {

// What the reader did at the keyboard, with the mouse or to the window.
struct LiveInput {
    enum class Kind { PageKey, Pause, Step, Screenshot, End, PointerPress, PointerMove, PointerRelease };
    Kind kind = Kind::PageKey;
    Key key = Key::A;  // the key, for PageKey
    int x = 0;         // where the pointer is, for the Pointer kinds: px of the picture shown
    int y = 0;         // (the page's device pixels) from its top-left corner
};

// Where a live session shows its pictures and hears the reader: a window
// (live_window.h) or, in tests, a stand-in.
class Screen {
public:
    virtual ~Screen() = default;
    // Puts `picture` on the screen.
    virtual void show(const Image& picture) = 0;
    // Waits until the next frame is due and returns what the reader did since the last
    // call, oldest first.
    virtual std::vector<LiveInput> nextFrame() = 0;
    // The session is over; called once, after the last show(). Throws FileError when it
    // cannot do what it was asked to do at the end.
    virtual void close() {}
};

// Plays the page on `screen` until the reader ends the session, pressing the keys of
// options.keys at their frames and the reader's as they come (only the stage's keys,
// options.stage_keys; others are let go). With options.live.record, writes the
// session's key script there and prints the one command that replays it into pictures
// and a GIF. Returns the exit status: 0; 1 with one line on stderr when the key script
// cannot be written (the line then gives the script, so the session is not lost), or
// when a screenshot could not be saved (one line each, as it happens; the session goes on).
int run_live(PageScripts& scripts, Window& window, const Options& options, Screen& screen);

}  // namespace browser
