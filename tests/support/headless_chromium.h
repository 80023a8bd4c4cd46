// Running a page in headless Chromium and getting its result back. The page
// POSTs one text body to http://127.0.0.1:PORT/ (PORT: the placeholder
// LUTBAKE_RESULT_PORT in the page is replaced); a one-shot python3 server on
// a free loopback port writes it to a file, and Chromium, started here with
// its process id kept, is ended by that id once the result is in (or after
// `seconds`). --dump-dom was not used: it ends the run when the page looks
// idle, which under load came before the WebGPU promises settled.
#pragma once

#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

namespace lutbake::test {

inline std::string ReadWhole(const std::filesystem::path &path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Loads `page` (HTML text) from `dir` with the extra Chromium `flags` and
// returns the body the page posted, or "" (with what is known in *log).
inline std::string RunPage(const std::filesystem::path &dir, std::string page,
                           const std::string &flags, const std::string &environment, int seconds,
                           std::string *log) {
  namespace fs = std::filesystem;
  const fs::path portFile = dir / "port.txt", result = dir / "result.txt",
                 serverLog = dir / "server.log";
  fs::remove(portFile);
  fs::remove(result);
  std::ofstream(dir / "server.py")
      << "import http.server, sys\n"
         "class H(http.server.BaseHTTPRequestHandler):\n"
         "    def do_POST(self):\n"
         "        body = self.rfile.read(int(self.headers['Content-Length']))\n"
         "        open(sys.argv[2] + '.tmp', 'wb').write(body)\n"
         "        import os; os.replace(sys.argv[2] + '.tmp', sys.argv[2])\n"
         "        self.send_response(204); self.send_header('Access-Control-Allow-Origin', '*')\n"
         "        self.end_headers()\n"
         "    def log_message(self, *args): pass\n"
         "s = http.server.HTTPServer(('127.0.0.1', 0), H)\n"
         "open(sys.argv[1] + '.tmp', 'w').write(str(s.server_address[1]))\n"
         "import os; os.replace(sys.argv[1] + '.tmp', sys.argv[1])\n"
         "s.handle_request()\n";
  const fs::path serverPid = dir / "server.pid", chromiumPid = dir / "chromium.pid";
  std::system(("timeout " + std::to_string(seconds + 10) + " python3 '" +
               (dir / "server.py").string() + "' '" + portFile.string() + "' '" + result.string() +
               "' > '" + serverLog.string() + "' 2>&1 & echo $! > '" + serverPid.string() + "'")
                  .c_str());
  const auto start = std::chrono::steady_clock::now();
  const auto elapsed = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  while (!fs::exists(portFile) && elapsed() < 10)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  const std::string port = ReadWhole(portFile);
  if (port.empty()) {
    *log = "the result server did not start: " + ReadWhole(serverLog);
    return "";
  }
  for (size_t at; (at = page.find("LUTBAKE_RESULT_PORT")) != std::string::npos;)
    page.replace(at, 19, port);
  std::ofstream(dir / "page.html") << page;
  const fs::path chromiumLog = dir / "chromium.log";
  std::system((environment + " timeout " + std::to_string(seconds) +
               " chromium --headless=new --no-sandbox --no-first-run --disable-extensions "
               "--disable-background-networking --user-data-dir='" +
               (dir / "profile").string() + "' --enable-logging=stderr --v=0 " + flags +
               " 'file://" + (dir / "page.html").string() + "' > '" + chromiumLog.string() +
               "' 2>&1 & echo $! > '" + chromiumPid.string() + "'")
                  .c_str());
  while (!fs::exists(result) && elapsed() < seconds)
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  // End the two processes started here, by their ids (timeout passes the
  // signal on to chromium).
  for (const fs::path &pidFile : {chromiumPid, serverPid}) {
    const long pid = std::atol(ReadWhole(pidFile).c_str());
    if (pid > 0) ::kill(static_cast<pid_t>(pid), SIGTERM);
  }
  // Wait (at most 10 s) for them to be gone, so that the caller can remove
  // `dir`: Chromium writes its profile while it shuts down.
  for (const fs::path &pidFile : {chromiumPid, serverPid}) {
    const long pid = std::atol(ReadWhole(pidFile).c_str());
    const auto waitStart = std::chrono::steady_clock::now();
    while (pid > 0 && ::kill(static_cast<pid_t>(pid), 0) == 0 &&
           std::chrono::steady_clock::now() - waitStart < std::chrono::seconds(10))
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  const std::string body = ReadWhole(result);
  if (body.empty())
    *log = "no result from the page within the time; Chromium's log:\n" +
           ReadWhole(chromiumLog).substr(0, 4000);
  return body;
}

// Removes a directory a browser ran in. Chromium's helper processes can
// still be writing its profile for a moment after the main one has ended
// (a file vanishing under remove_all once failed a CI run), so retry for a
// few seconds before giving up quietly: a temporary left behind is not a
// test failure.
inline void RemoveBrowserDirectory(const std::filesystem::path &dir) {
  for (int attempt = 0; attempt < 50; ++attempt) {
    std::error_code error;
    std::filesystem::remove_all(dir, error);
    if (!error) return;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
}

}  // namespace lutbake::test
