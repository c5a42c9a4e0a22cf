// SDL window + ImGui + frame loop.
#include "app.h"

#include <imgui.h>
#include <imgui_impl_sdl.h>
#include <imgui_impl_sdlrenderer.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <optional>

#include "adaptive_resolution.h"
#include "frame_capture.h"
#include "frame_texture.h"
#include "overlay.h"
#include "script_events.h"
#include "script_player.h"

namespace luxel::viewer {
namespace {

constexpr double kFrameSeconds = 1.0 / 60.0;  // the UI loop's pace; rendering runs apart

double now() {
    using Clock = std::chrono::steady_clock;
    static const Clock::time_point start = Clock::now();
    return std::chrono::duration<double>(Clock::now() - start).count();
}

// The frame keeps its aspect ratio, centred in the window.
ViewRect fitRect(int windowW, int windowH, int frameW, int frameH) {
    const double scale =
        std::min(static_cast<double>(windowW) / frameW, static_cast<double>(windowH) / frameH);
    ViewRect r;
    r.width = frameW * scale;
    r.height = frameH * scale;
    r.x = (windowW - r.width) * 0.5;
    r.y = (windowH - r.height) * 0.5;
    return r;
}

// SDL window, renderer and ImGui context, released in reverse order.
struct Window {
    SDL_Window* window = nullptr;
    SDL_Renderer* renderer = nullptr;
    bool imgui = false;
    ~Window() {
        if (imgui) {
            ImGui_ImplSDLRenderer_Shutdown();
            ImGui_ImplSDL2_Shutdown();
            ImGui::DestroyContext();
        }
        if (renderer) SDL_DestroyRenderer(renderer);
        if (window) SDL_DestroyWindow(window);
        SDL_Quit();
    }
};

int fail(const std::string& message, int code) {
    std::fprintf(stderr, "luxel-view: error: %s\n", message.c_str());
    return code;
}

}  // namespace

int runApp(const ViewerOptions& options, ViewerMode& mode, std::optional<Script> script,
           int windowWidth, int windowHeight) {
    if (SDL_Init(SDL_INIT_VIDEO) != 0) {
        const std::string why = SDL_GetError();
        SDL_Quit();
        return fail("cannot open a window (" + why +
                        "); is there a display? Set DISPLAY or run under xvfb-run",
                    kExitNoDisplay);
    }
    // Without a display SDL falls back to its offscreen driver, which would run invisibly
    // forever; only an explicit SDL_VIDEODRIVER may choose it.
    const std::string driver = SDL_GetCurrentVideoDriver() ? SDL_GetCurrentVideoDriver() : "";
    if ((driver == "offscreen" || driver == "dummy") && !SDL_getenv("SDL_VIDEODRIVER")) {
        SDL_Quit();
        return fail("cannot open a window (no display: SDL found only its '" + driver +
                        "' driver); set DISPLAY or run under xvfb-run",
                    kExitNoDisplay);
    }
    Window w;
    const std::string title = "luxel-view: " + options.scene;
    w.window = SDL_CreateWindow(title.c_str(), SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED,
                                windowWidth, windowHeight, SDL_WINDOW_RESIZABLE);
    if (!w.window)
        return fail(std::string("cannot create a window: ") + SDL_GetError(), kExitNoDisplay);
    SDL_SetHint(SDL_HINT_RENDER_SCALE_QUALITY, "linear");  // smooth upscaling of small frames
    w.renderer = SDL_CreateRenderer(w.window, -1, SDL_RENDERER_ACCELERATED);
    if (!w.renderer) w.renderer = SDL_CreateRenderer(w.window, -1, SDL_RENDERER_SOFTWARE);
    if (!w.renderer) {
        return fail(std::string("cannot create a renderer: ") + SDL_GetError(), kExitNoDisplay);
    }
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini: runs are reproducible
    ImGui::StyleColorsDark();
    ImGui_ImplSDL2_InitForSDLRenderer(w.window);
    ImGui_ImplSDLRenderer_Init(w.renderer);
    w.imgui = true;

    const std::string scriptName = script ? script->name : "";
    std::optional<ScriptPlayer> player;
    if (script) player.emplace(std::move(*script));
    ScriptedMouse scriptedMouse;
    FrameRecorder recorder(options.recordFrames, options.recordDir);
    FrameTexture texture;
    RateMeter windowRate, renderRate;
    bool showPanels = !options.hideOverlay;
    std::string lastScreenshot;
    std::shared_ptr<const Frame> shown;
    int exitCode = 0;
    bool quit = false;
    int framesRendered = 0;
    double renderMillisecondsSum = 0.0;
    double previous = now();
    // Without --internal-size or --internal-scale, the internal size grows from the mode's cheap
    // start to the largest that keeps --target-fps (adaptive_resolution.h).
    std::optional<AdaptiveResolution> adaptive;
    if (options.targetFps > 0.0 && options.internalWidth == 0 && options.internalScale <= 0.0f) {
        adaptive.emplace(ImageSize{mode.internalWidth(), mode.internalHeight()},
                         1000.0 / options.targetFps);
    }

    while (!quit) {
        const double frameStart = now();
        int winW = 0, winH = 0;
        SDL_GetRendererOutputSize(w.renderer, &winW, &winH);
        const ViewRect view = fitRect(std::max(winW, 1), std::max(winH, 1), mode.internalWidth(),
                                      mode.internalHeight());
        const ImGuiIO& io = ImGui::GetIO();
        auto dispatch = [&](const SDL_Event& e) {
            if (e.type == SDL_KEYDOWN) {
                const SDL_Keycode k = e.key.keysym.sym;
                if (k == SDLK_ESCAPE) quit = true;
                if (k == SDLK_F1) showPanels = !showPanels;
                if (k == SDLK_F12 && shown) {
                    lastScreenshot = nextScreenshotName();
                    if (Status s = writeFramePng(lastScreenshot, *shown); !s) {
                        lastScreenshot = s.error().message();
                    }
                }
            }
            mode.handleEvent(e, view);
        };

        // Real input: the panels get it first.
        SDL_Event event;
        while (SDL_PollEvent(&event)) {
            ImGui_ImplSDL2_ProcessEvent(&event);
            if (event.type == SDL_QUIT) quit = true;
            if (event.type == SDL_WINDOWEVENT) mode.handleEvent(event, view);
            const bool mouse = event.type == SDL_MOUSEBUTTONDOWN ||
                               event.type == SDL_MOUSEBUTTONUP || event.type == SDL_MOUSEMOTION ||
                               event.type == SDL_MOUSEWHEEL;
            const bool key = event.type == SDL_KEYDOWN || event.type == SDL_KEYUP;
            if ((mouse && showPanels && io.WantCaptureMouse) ||
                (key && showPanels && io.WantCaptureKeyboard)) {
                continue;
            }
            if (mouse || key) dispatch(event);
        }

        // Scripted input: straight to the handlers, past the panels, so runs are reproducible.
        std::vector<std::string> screenshotsAfterDraw;
        if (player) {
            ScriptClock clock{frameStart, mode.frameCurrent(), mode.frameConverged()};
            for (const ScriptEvent& e : player->due(clock)) {
                switch (e.command) {
                    case ScriptCommand::Quit:
                        quit = true;
                        break;
                    case ScriptCommand::Screenshot:
                        if (auto frame = mode.latestFrame(nullptr); !frame) {
                            exitCode = fail(scriptName + ":" + std::to_string(e.line) +
                                                ": no frame to write yet",
                                            kExitBadInput);
                            quit = true;
                        } else if (Status s = writeFramePng(e.path, *frame); !s) {
                            exitCode = fail(s.error().message(), kExitBadInput);
                            quit = true;
                        }
                        break;
                    case ScriptCommand::Resize:
                        SDL_SetWindowSize(w.window, e.x, e.y);
                        break;
                    case ScriptCommand::ScreenshotWindow:
                        screenshotsAfterDraw.push_back(e.path);
                        break;
                    default:
                        for (const SDL_Event& s :
                             toSdlEvents(e, scriptedMouse, SDL_GetWindowID(w.window))) {
                            dispatch(s);
                        }
                }
            }
            if (player->failure()) {
                exitCode = fail(*player->failure(), kExitBadInput);
                quit = true;
            }
        }

        const double t = now();
        mode.update(t - previous);
        previous = t;

        bool fresh = false;
        if (auto frame = mode.latestFrame(&fresh); frame && fresh) {
            shown = frame;
            renderRate.tick(t);
            ++framesRendered;
            renderMillisecondsSum += frame->renderMilliseconds;
            texture.update(w.renderer, shown->picture);
            // A progressive render's later passes refine a still view: their time is not the
            // interactive rate, and a new size would throw the accumulation away.
            if (adaptive && !shown->accumulating) {
                adaptive->setLargest({std::max(1, static_cast<int>(view.width + 0.5)),
                                      std::max(1, static_cast<int>(view.height + 0.5))});
                const ImageSize rendered{shown->picture.width(), shown->picture.height()};
                if (auto next = adaptive->frameRendered(rendered, shown->renderMilliseconds, t)) {
                    mode.setInternalSize(next->width, next->height);
                }
            }
            if (Status s = recorder.offer(*shown); !s) {
                exitCode = fail(s.error().message(), kExitBadInput);
                quit = true;
            }
        }
        windowRate.tick(t);

        ImGui_ImplSDLRenderer_NewFrame();
        ImGui_ImplSDL2_NewFrame();
        ImGui::NewFrame();
        if (showPanels) {
            OverlayInfo info{shown.get(),
                             windowRate.perSecond(),
                             renderRate.perSecond(),
                             winW,
                             winH,
                             lastScreenshot,
                             adaptive ? options.targetFps : 0.0};
            drawOverlay(info, mode);
        }
        mode.drawOverFrame();
        ImGui::Render();
        SDL_SetRenderDrawColor(w.renderer, 16, 16, 20, 255);
        SDL_RenderClear(w.renderer);
        if (texture.texture()) {
            const ViewRect r =
                fitRect(std::max(winW, 1), std::max(winH, 1), texture.width(), texture.height());
            const SDL_Rect dst{static_cast<int>(r.x + 0.5), static_cast<int>(r.y + 0.5),
                               static_cast<int>(r.width + 0.5), static_cast<int>(r.height + 0.5)};
            SDL_RenderCopy(w.renderer, texture.texture(), nullptr, &dst);
        }
        ImGui_ImplSDLRenderer_RenderDrawData(ImGui::GetDrawData());
        for (const std::string& path : screenshotsAfterDraw) {
            if (Status s = writeWindowPng(path, w.renderer); !s) {
                exitCode = fail(s.error().message(), kExitBadInput);
                quit = true;
            }
        }
        SDL_RenderPresent(w.renderer);

        // Keep the UI thread light so the render thread gets the cores.
        const double spent = now() - frameStart;
        if (spent < kFrameSeconds) SDL_Delay(static_cast<Uint32>((kFrameSeconds - spent) * 1000.0));
    }
    // One summary line: what ran where, and how fast (used by tests and for measurements).
    if (shown) {
        std::printf(
            "luxel-view: %s mode, %dx%d internal, backend %s (%s), %d frames, "
            "mean render %.1f ms, window %.0f fps\n",
            mode.name().c_str(), mode.internalWidth(), mode.internalHeight(),
            shown->backend.c_str(), shown->device.c_str(), framesRendered,
            renderMillisecondsSum / framesRendered, windowRate.perSecond());
    }
    if (recorder.written() > 0) {
        std::printf("luxel-view: recorded %d frames into %s\n", recorder.written(),
                    options.recordDir.c_str());
    }
    return exitCode;
}

}  // namespace luxel::viewer
