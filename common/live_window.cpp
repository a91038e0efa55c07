#include "live_window.h"

#if BROWSER_HAS_SDL

#include <SDL.h>

#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <vector>

#include "png_io.h"

namespace browser {
namespace {

// The keys a live window passes on: the page's keys, and the four of the session.
std::optional<LiveInput> input_of(const SDL_KeyboardEvent& event) {
    using Kind = LiveInput::Kind;
    const SDL_Keycode code = event.keysym.sym;
    if (code >= SDLK_a && code <= SDLK_z) {
        return LiveInput{Kind::PageKey, static_cast<Key>(static_cast<int>(Key::A) + (code - SDLK_a))};
    }
    if (code >= SDLK_0 && code <= SDLK_9) {
        return LiveInput{Kind::PageKey, static_cast<Key>(static_cast<int>(Key::Digit0) + (code - SDLK_0))};
    }
    // The keypad's codes run 1, 2, ..., 9, 0.
    if (code >= SDLK_KP_1 && code <= SDLK_KP_9) {
        return LiveInput{Kind::PageKey, static_cast<Key>(static_cast<int>(Key::Digit1) + (code - SDLK_KP_1))};
    }
    switch (code) {
        case SDLK_KP_0: return LiveInput{Kind::PageKey, Key::Digit0};
        case SDLK_COMMA: return LiveInput{Kind::PageKey, Key::Comma};
        case SDLK_UP: return LiveInput{Kind::PageKey, Key::Up};
        case SDLK_DOWN: return LiveInput{Kind::PageKey, Key::Down};
        case SDLK_SLASH: return LiveInput{Kind::PageKey, Key::Slash};
        // A held Space would pause and go on at every repeat; a held period steps on.
        case SDLK_SPACE:
            if (event.repeat != 0) return std::nullopt;
            return LiveInput{Kind::Pause};
        case SDLK_PERIOD: return LiveInput{Kind::Step};
        case SDLK_F12:
            if (event.repeat != 0) return std::nullopt;
            return LiveInput{Kind::Screenshot};
        case SDLK_ESCAPE: return LiveInput{Kind::End};
        default: return std::nullopt;
    }
}

// A scripted event of the --live-events test hook: a key, or the close button (0), or
// the left mouse button pressed, moved with or let go at a point of the window.
struct ScriptedEvent {
    SDL_Keycode key = 0;
    Uint32 mouse = 0;  // SDL_MOUSEBUTTONDOWN, SDL_MOUSEMOTION or SDL_MOUSEBUTTONUP; 0 for a key
    int x = 0, y = 0;
};

// "press:X,Y", "move:X,Y" or "release:X,Y": the mouse event, or nothing.
std::optional<ScriptedEvent> mouse_event(const std::string& name) {
    const std::size_t colon = name.find(':');
    const std::size_t comma = name.find(',');
    if (colon == std::string::npos || comma == std::string::npos || comma < colon) return std::nullopt;
    const std::string kind = name.substr(0, colon);
    ScriptedEvent event;
    event.mouse = kind == "press"     ? SDL_MOUSEBUTTONDOWN
                  : kind == "move"    ? SDL_MOUSEMOTION
                  : kind == "release" ? SDL_MOUSEBUTTONUP
                                      : 0;
    const char* x_end = name.data() + comma;
    const char* y_end = name.data() + name.size();
    const auto [x_stop, x_error] = std::from_chars(name.data() + colon + 1, x_end, event.x);
    const auto [y_stop, y_error] = std::from_chars(x_end + 1, y_end, event.y);
    if (event.mouse == 0 || x_error != std::errc{} || x_stop != x_end || y_error != std::errc{} || y_stop != y_end) {
        return std::nullopt;
    }
    return event;
}

std::map<int, std::vector<ScriptedEvent>> read_events(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw LiveWindowError("--live-events: cannot read \"" + file.string() + "\"");
    const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    std::map<int, std::vector<ScriptedEvent>> events;
    std::size_t pos = 0;
    while ((pos = text.find_first_not_of(" \t\r\n", pos)) != std::string::npos) {
        const std::size_t end = std::min(text.find_first_of(" \t\r\n", pos), text.size());
        const std::string token = text.substr(pos, end - pos);
        pos = end;
        const std::size_t at = token.rfind('@');
        int refresh = 0;
        const char* first = token.data() + (at == std::string::npos ? token.size() : at + 1);
        const char* last = token.data() + token.size();
        const auto [stop, error] = std::from_chars(first, last, refresh);
        const std::string name = token.substr(0, at);
        const std::optional<ScriptedEvent> mouse = mouse_event(name);
        const SDL_Keycode key = name == "close" || mouse ? 0 : SDL_GetKeyFromName(name.c_str());
        if (at == std::string::npos || error != std::errc{} || stop != last || refresh < 1 ||
            (name != "close" && !mouse && key == SDLK_UNKNOWN)) {
            throw LiveWindowError(
                "--live-events: bad token \"" + token +
                "\" (NAME@REFRESH, NAME an SDL key name, close, or press:X,Y, move:X,Y, release:X,Y)");
        }
        events[refresh].push_back(mouse ? *mouse : ScriptedEvent{key});
    }
    return events;
}

struct WindowDeleter {
    void operator()(SDL_Window* window) const { SDL_DestroyWindow(window); }
};
struct RendererDeleter {
    void operator()(SDL_Renderer* renderer) const { SDL_DestroyRenderer(renderer); }
};
struct TextureDeleter {
    void operator()(SDL_Texture* texture) const { SDL_DestroyTexture(texture); }
};

// Whether the environment names a display, or a video driver, for SDL to use.
bool display_named() {
    for (const char* name : {"SDL_VIDEODRIVER", "DISPLAY", "WAYLAND_DISPLAY"}) {
        const char* value = std::getenv(name);
        if (value != nullptr && *value != '\0') return true;
    }
    return false;
}

[[noreturn]] void fail(const std::string& what) { throw LiveWindowError("--live: " + what + ": " + SDL_GetError()); }

class SdlWindow final : public Screen {
public:
    explicit SdlWindow(const LiveWindowSettings& settings) : settings_(settings) {
        if (!settings.events.empty()) scripted_ = read_events(settings.events);
        // SIGINT and SIGTERM stay the run's (interruption.h): SDL would turn them into a
        // quiet end of the session, exit status 0.
        SDL_SetHint(SDL_HINT_NO_SIGNAL_HANDLERS, "1");
        // With no display named SDL tries one driver after another, may settle on one
        // that shows nothing, and runs a session no one sees until it is killed.
        if (!display_named()) {
            throw LiveWindowError(
                "--live: no display to open a window on (DISPLAY and WAYLAND_DISPLAY are unset; "
                "SDL_VIDEODRIVER names a driver explicitly)");
        }
        if (SDL_InitSubSystem(SDL_INIT_VIDEO) != 0) fail("cannot open a window");
    }
    ~SdlWindow() override {
        texture_.reset();
        renderer_.reset();
        window_.reset();
        SDL_QuitSubSystem(SDL_INIT_VIDEO);
        SDL_Quit();
    }
    SdlWindow(const SdlWindow&) = delete;
    SdlWindow& operator=(const SdlWindow&) = delete;

    void show(const Image& picture) override {
        if (!window_) open(picture.width, picture.height);
        if (picture.width != width_ || picture.height != height_) resize(picture.width, picture.height);
        if (SDL_UpdateTexture(texture_.get(), nullptr, picture.rgba.data(), picture.width * 4) != 0) {
            fail("cannot update the picture");
        }
        // One picture pixel a window pixel, from the top-left corner: never stretched.
        const SDL_Rect place{0, 0, picture.width, picture.height};
        SDL_RenderClear(renderer_.get());
        if (SDL_RenderCopy(renderer_.get(), texture_.get(), nullptr, &place) != 0) fail("cannot draw the picture");
        if (!settings_.screenshot.empty()) {
            shown_ = Image(picture.width, picture.height);
            if (SDL_RenderReadPixels(renderer_.get(), &place, SDL_PIXELFORMAT_RGBA32, shown_.rgba.data(),
                                     shown_.width * 4) != 0) {
                fail("cannot read the picture back");
            }
        }
        SDL_RenderPresent(renderer_.get());  // waits for the display's refresh where the renderer can
    }

    std::vector<LiveInput> nextFrame() override {
        waitForFrameTime();
        ++refresh_;
        if (const auto due = scripted_.find(refresh_); due != scripted_.end()) {
            for (const ScriptedEvent& scripted : due->second) push(scripted);
        }
        std::vector<LiveInput> inputs;
        SDL_Event event;
        while (SDL_PollEvent(&event) != 0) {
            if (event.type == SDL_QUIT ||
                (event.type == SDL_WINDOWEVENT && event.window.event == SDL_WINDOWEVENT_CLOSE)) {
                inputs.push_back({LiveInput::Kind::End});
            } else if (event.type == SDL_KEYDOWN) {
                if (const auto input = input_of(event.key)) inputs.push_back(*input);
            } else if ((event.type == SDL_MOUSEBUTTONDOWN || event.type == SDL_MOUSEBUTTONUP) &&
                       event.button.button == SDL_BUTTON_LEFT) {
                const auto kind =
                    event.type == SDL_MOUSEBUTTONDOWN ? LiveInput::Kind::PointerPress : LiveInput::Kind::PointerRelease;
                inputs.push_back({.kind = kind, .x = event.button.x, .y = event.button.y});
            } else if (event.type == SDL_MOUSEMOTION) {
                inputs.push_back({.kind = LiveInput::Kind::PointerMove, .x = event.motion.x, .y = event.motion.y});
            }
        }
        return inputs;
    }

    void close() override {
        if (!settings_.screenshot.empty()) write_png(settings_.screenshot, shown_);
    }

private:
    void open(int width, int height) {
        window_.reset(SDL_CreateWindow(settings_.title.c_str(), SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED, width,
                                       height, SDL_WINDOW_SHOWN));
        if (!window_) fail("cannot open a window");
        // Vsync where the renderer has it; any renderer where the first choice fails.
        renderer_.reset(SDL_CreateRenderer(window_.get(), -1, SDL_RENDERER_PRESENTVSYNC));
        if (!renderer_) renderer_.reset(SDL_CreateRenderer(window_.get(), -1, 0));
        if (!renderer_) fail("cannot draw in the window");
        makeTexture(width, height);
        SDL_SetRenderDrawColor(renderer_.get(), 0, 0, 0, 255);
        SDL_StopTextInput();  // keys only: no input method composing text
        next_frame_ms_ = now_ms() + settings_.frame_ms;
    }

    void makeTexture(int width, int height) {
        texture_.reset(
            SDL_CreateTexture(renderer_.get(), SDL_PIXELFORMAT_RGBA32, SDL_TEXTUREACCESS_STREAMING, width, height));
        if (!texture_) fail("cannot make a picture of that size");
        SDL_SetTextureBlendMode(texture_.get(), SDL_BLENDMODE_NONE);  // copied as it is, alpha included
        width_ = width;
        height_ = height;
    }

    // The page grew (the overlay's legend gets its band the first time the overlay
    // comes on, page.h): the window grows with it, one picture pixel a window pixel.
    void resize(int width, int height) {
        SDL_SetWindowSize(window_.get(), width, height);
        makeTexture(width, height);
    }

    static double now_ms() {
        return 1000.0 * static_cast<double>(SDL_GetPerformanceCounter()) /
               static_cast<double>(SDL_GetPerformanceFrequency());
    }

    // Frames come no sooner than frame_ms apart. A late frame is not made up for by
    // hurrying the ones after it: the next is due frame_ms after it.
    void waitForFrameTime() {
        const double now = now_ms();
        if (now < next_frame_ms_) SDL_Delay(static_cast<Uint32>(next_frame_ms_ - now));
        next_frame_ms_ = std::max(next_frame_ms_, now) + settings_.frame_ms;
    }

    void push(const ScriptedEvent& scripted) {
        SDL_Event event{};
        const Uint32 window_id = window_ ? SDL_GetWindowID(window_.get()) : 0;
        if (scripted.mouse == SDL_MOUSEMOTION) {
            event.type = SDL_MOUSEMOTION;
            event.motion.windowID = window_id;
            event.motion.state = SDL_BUTTON_LMASK;
            event.motion.x = scripted.x;
            event.motion.y = scripted.y;
        } else if (scripted.mouse != 0) {
            event.type = scripted.mouse;
            event.button.windowID = window_id;
            event.button.button = SDL_BUTTON_LEFT;
            event.button.state = scripted.mouse == SDL_MOUSEBUTTONDOWN ? SDL_PRESSED : SDL_RELEASED;
            event.button.clicks = 1;
            event.button.x = scripted.x;
            event.button.y = scripted.y;
        } else if (scripted.key == 0) {
            event.type = SDL_WINDOWEVENT;
            event.window.windowID = window_id;
            event.window.event = SDL_WINDOWEVENT_CLOSE;
        } else {
            event.type = SDL_KEYDOWN;
            event.key.windowID = window_id;
            event.key.state = SDL_PRESSED;
            event.key.keysym.sym = scripted.key;
            event.key.keysym.scancode = SDL_GetScancodeFromKey(scripted.key);
        }
        if (SDL_PushEvent(&event) < 0) fail("cannot push a scripted event");
    }

    LiveWindowSettings settings_;
    std::map<int, std::vector<ScriptedEvent>> scripted_;  // by refresh
    int refresh_ = 0;
    double next_frame_ms_ = 0.0;
    std::unique_ptr<SDL_Window, WindowDeleter> window_;
    std::unique_ptr<SDL_Renderer, RendererDeleter> renderer_;
    std::unique_ptr<SDL_Texture, TextureDeleter> texture_;
    int width_ = 0, height_ = 0;  // the texture's, which is the picture's
    Image shown_;                 // the last picture shown, as read back (screenshot hook only)
};

}  // namespace

std::unique_ptr<Screen> open_live_window(const LiveWindowSettings& settings) {
    return std::make_unique<SdlWindow>(settings);
}

}  // namespace browser

#else  // no SDL2

namespace browser {

std::unique_ptr<Screen> open_live_window(const LiveWindowSettings&) {
    throw LiveWindowError(std::string(kNoLiveSupport));
}

}  // namespace browser

#endif
