// The --script parser and its frame-by-frame player (no display needed).
#include <gtest/gtest.h>

#include <filesystem>

#include <sys/stat.h>

#include "input_script.h"
#include "script_player.h"
#include "support/temp_dir.h"

namespace luxel::viewer {
namespace {

bool anyKey(const std::string& name) {
    return name != "NoSuchKey";
}

TEST(InputScript, ParsesEveryCommand) {
    const char* text =
        "# drag the light\n"
        "wait_render\n"
        "at 0.5 key Space\n"
        "key ctrl+shift+s   # save\n"
        "mouse_down 10 20\n"
        "mouse_move 30 40\n"
        "mouse_up 30 40 right\n"
        "click 5 6 middle\n"
        "\n"
        "wait 0.25\n"
        "wait_frames 3\n"
        "screenshot out.png\n"
        "screenshot_window win.PNG\n"
        "wait_converged\n"
        "resize 640 360\n"
        "quit\n";
    auto script = parseScript(text, "s.txt", anyKey);
    ASSERT_TRUE(script) << script.error().message();
    const auto& e = script->events;
    ASSERT_EQ(e.size(), 14u);
    EXPECT_EQ(e[0].command, ScriptCommand::WaitRender);
    EXPECT_EQ(e[1].command, ScriptCommand::Key);
    EXPECT_DOUBLE_EQ(e[1].at, 0.5);
    EXPECT_EQ(e[1].key.name, "Space");
    EXPECT_EQ(e[1].line, 3);
    EXPECT_TRUE(e[2].key.ctrl && e[2].key.shift && !e[2].key.alt);
    EXPECT_EQ(e[2].key.name, "s");
    EXPECT_EQ(e[3].x, 10);
    EXPECT_EQ(e[3].y, 20);
    EXPECT_EQ(e[5].button, MouseButton::Right);
    EXPECT_EQ(e[6].button, MouseButton::Middle);
    EXPECT_DOUBLE_EQ(e[7].seconds, 0.25);
    EXPECT_EQ(e[8].frames, 3);
    EXPECT_EQ(e[9].path, "out.png");
    EXPECT_EQ(e[10].command, ScriptCommand::ScreenshotWindow);
    EXPECT_EQ(e[12].command, ScriptCommand::Resize);
    EXPECT_EQ(e[12].x, 640);
    EXPECT_EQ(e[12].y, 360);
    EXPECT_EQ(e[13].command, ScriptCommand::Quit);
}

TEST(InputScript, ErrorsNameTheFileAndLine) {
    struct Case {
        const char* text;
        const char* needle;
    };
    const Case cases[] = {
        {"quit\njump 1 2\n", "s.txt:2: unknown command 'jump'"},
        {"key NoSuchKey\n", "s.txt:1: key: unknown key 'NoSuchKey'"},
        {"\n\nmouse_down 1\n", "s.txt:3: mouse_down: expected"},
        {"mouse_down 1 x\n", "s.txt:1: mouse_down: mouse position"},
        {"click 1 2 thumb\n", "s.txt:1: click: mouse button 'thumb'"},
        {"wait -1\n", "s.txt:1: wait: '-1'"},
        {"wait_frames 2.5\n", "s.txt:1: wait_frames: '2.5'"},
        {"screenshot out.jpg\n", "s.txt:1: screenshot: screenshot file 'out.jpg'"},
        {"at soon quit\n", "s.txt:1: expected 'at SECONDS"},
        {"quit now\n", "s.txt:1: quit: expected no arguments"},
        {"resize 0 10\n", "s.txt:1: resize: window size '0 10'"},
        {"wheel\n", "s.txt:1: wheel: expected 'wheel NOTCHES'"},
        {"wheel 0\n", "s.txt:1: wheel: '0' is not a wheel step"},
        {"wheel up\n", "s.txt:1: wheel: 'up' is not a wheel step"},
        {"wait 1e308\n", "s.txt:1: wait: '1e308' is not a number of seconds in 0..3600"},
        {"wait 3600.5\n", "s.txt:1: wait: '3600.5'"},
        {"wait nan\n", "s.txt:1: wait: 'nan'"},
        {"at 1e308 quit\n", "s.txt:1: expected 'at SECONDS COMMAND ...' with SECONDS in 0..3600"},
        {"at inf quit\n", "s.txt:1: expected 'at SECONDS"},
    };
    for (const Case& c : cases) {
        auto script = parseScript(c.text, "s.txt", anyKey);
        ASSERT_FALSE(script) << c.text;
        EXPECT_NE(script.error().message().find(c.needle), std::string::npos)
            << script.error().message();
    }
}

TEST(InputScript, WheelTakesSignedNotches) {
    auto script = parseScript("wheel 3\nwheel -2\n", "s.txt", anyKey);
    ASSERT_TRUE(script) << script.error().message();
    ASSERT_EQ(script->events.size(), 2u);
    EXPECT_EQ(script->events[0].command, ScriptCommand::Wheel);
    EXPECT_EQ(script->events[0].y, 3);
    EXPECT_EQ(script->events[1].y, -2);
}

TEST(InputScript, MissingFileIsAnError) {
    auto script = loadScript("/nonexistent/script.txt", anyKey);
    ASSERT_FALSE(script);
    EXPECT_NE(script.error().message().find("/nonexistent/script.txt"), std::string::npos);
}

TEST(InputScript, TheLongestWaitIsAccepted) {
    auto script = parseScript("wait 3600\nat 3600 quit\n", "s.txt", anyKey);
    ASSERT_TRUE(script) << script.error().message();
    EXPECT_EQ(script->events[0].seconds, 3600.0);
    EXPECT_EQ(script->events[1].at, 3600.0);
}

TEST(InputScript, ADirectoryIsNotAScript) {
    const test::TempDir tmp;
    const std::filesystem::path& dir = tmp.dir();
    auto script = loadScript(dir.string(), anyKey);
    ASSERT_FALSE(script);
    EXPECT_NE(script.error().message().find(dir.string() + "': Is a directory"), std::string::npos)
        << script.error().message();
}

TEST(InputScript, AFifoIsRefusedWithoutBlocking) {
    const test::TempDir tmp;
    const std::string fifo = tmp.path("script.fifo");
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    auto script = loadScript(fifo, anyKey);  // opening a FIFO for reading would wait for a writer
    ASSERT_FALSE(script);
    EXPECT_NE(script.error().message().find("not a regular file"), std::string::npos)
        << script.error().message();
}

Script parse(const char* text) {
    auto script = parseScript(text, "s.txt", anyKey);
    EXPECT_TRUE(script);
    return *script;
}

TEST(ScriptPlayer, WaitRenderHoldsEventsUntilTheFrameIsCurrent) {
    ScriptPlayer player(parse("key a\nwait_render\nkey b\nscreenshot x.png\nkey c\nquit\n"));
    ScriptClock clock;
    auto events = player.due(clock);
    ASSERT_EQ(events.size(), 1u);  // key a, then waiting
    EXPECT_EQ(events[0].key.name, "a");
    EXPECT_TRUE(player.due(clock).empty());
    clock.renderCurrent = true;
    events = player.due(clock);
    ASSERT_EQ(events.size(), 2u);  // key b and the screenshot, which ends the frame's batch
    EXPECT_EQ(events[1].command, ScriptCommand::Screenshot);
    events = player.due(clock);
    ASSERT_EQ(events.size(), 2u);
    EXPECT_EQ(events[1].command, ScriptCommand::Quit);
    EXPECT_TRUE(player.finished());
}

TEST(ScriptPlayer, WaitFramesAndSecondsAndAt) {
    ScriptPlayer player(parse("wait_frames 2\nkey a\nwait 1.0\nkey b\nat 5 key c\n"));
    ScriptClock clock;
    EXPECT_TRUE(player.due(clock).empty());   // frame 0
    EXPECT_TRUE(player.due(clock).empty());   // frame 1
    EXPECT_EQ(player.due(clock).size(), 1u);  // frame 2: key a, then the 1 s wait starts
    clock.seconds = 0.9;
    EXPECT_TRUE(player.due(clock).empty());
    clock.seconds = 1.0;
    EXPECT_EQ(player.due(clock).size(), 1u);  // key b; key c waits for t = 5
    clock.seconds = 4.9;
    EXPECT_TRUE(player.due(clock).empty());
    clock.seconds = 5.0;
    EXPECT_EQ(player.due(clock).size(), 1u);
    EXPECT_TRUE(player.finished());
}

TEST(ScriptPlayer, AWaitThatNeverEndsTimesOutWithItsLine) {
    ScriptPlayer player(parse("quit\n"), 10.0);
    ScriptPlayer stuck(parse("\nwait_converged\nquit\n"), 10.0);
    ScriptClock clock;
    clock.renderCurrent = true;  // current but never converged
    EXPECT_TRUE(stuck.due(clock).empty());
    clock.seconds = 11.0;
    EXPECT_TRUE(stuck.due(clock).empty());
    ASSERT_TRUE(stuck.failure());
    EXPECT_NE(stuck.failure()->find("s.txt:2:"), std::string::npos) << *stuck.failure();
    EXPECT_FALSE(player.failure());
}

}  // namespace
}  // namespace luxel::viewer
