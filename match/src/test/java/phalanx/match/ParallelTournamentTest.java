package phalanx.match;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.TimeUnit;
import java.util.stream.Collectors;

import static org.junit.jupiter.api.Assertions.*;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

/**
 * The tournament's GNU parallel path (--jobs, --hosts), end to end through the real parallel, the real
 * scripts/lib/tools/tournament-job and tournament-ssh and the real Tournament main (in a JVM of its
 * own), with two stand-ins from src/test/resources/tournament: stand-in-game in place of
 * scripts/phalanx match (sleeps, then writes a result JSON in MatchResult's format; no server) and
 * fake-ssh in place of ssh (runs the command here, in a "home" of the host's own, so files reach the
 * tournament's folder only through parallel's --return). Skips when parallel (or, for the hosts test,
 * rsync) is not installed.
 */
class ParallelTournamentTest {
    @TempDir Path tmp;
    private static final Path RES = Path.of("match/src/test/resources/tournament").toAbsolutePath();

    private static void needParallel() {
        assumeTrue(ParallelHosts.available(),
                "GNU parallel is not installed (Debian package parallel; scripts/setup.sh installs it): the tournament's --jobs/--hosts path is not tested");
    }

    private static boolean rsync() {
        try {
            Process p = new ProcessBuilder("rsync", "--version").redirectErrorStream(true).start();
            p.getInputStream().readAllBytes();
            return p.waitFor(10, TimeUnit.SECONDS) && p.exitValue() == 0;
        } catch (IOException | InterruptedException e) {
            return false;
        }
    }

    /** The Tournament main in a JVM of its own, output to {@code log}. */
    private Process tournament(Path log, Map<String, String> env, String... args) throws IOException {
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Dphalanx.root=" + Path.of("").toAbsolutePath(), "-cp", System.getProperty("java.class.path"),
                "phalanx.match.Tournament", "--team", "A=a {port}", "--team", "B=b {port}", "--team", "C=c {port}",
                "--game-command", "bash " + RES.resolve("stand-in-game"), "--half-time", "300", "--sync"));
        cmd.addAll(List.of(args));
        ProcessBuilder pb = new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(ProcessBuilder.Redirect.appendTo(log.toFile()));
        pb.environment().putAll(env);
        return pb.start();
    }

    private static int finish(Process p) throws InterruptedException {
        assertTrue(p.waitFor(180, TimeUnit.SECONDS), "the tournament did not end in 180 s");
        return p.exitValue();
    }

    /** The joblog's lines: seq, host, exit. */
    private static List<String[]> joblog(Path out) throws IOException {
        return Files.readAllLines(out.resolve("joblog")).stream().skip(1).map(l -> l.split("\t")).toList();
    }

    /** How many times each tag has this event in the stand-in's ledger. */
    private static Map<String, Long> ledger(Path ledger, String event) throws IOException {
        return Files.readAllLines(ledger).stream().map(l -> l.split(" ")).filter(f -> f[0].equals(event))
                .collect(Collectors.groupingBy(f -> f[1], TreeMap::new, Collectors.counting()));
    }

    private static Map<String, Long> once(int games) {
        Map<String, Long> m = new TreeMap<>();
        for (int i = 1; i <= games; i++) m.put(Tournament.tag(i), 1L);
        return m;
    }

    @Test
    void theJobCommandPassesOnlyTheMatchOptionsAndRefusesFixedPorts() throws IOException {
        String[] argv = {"--team", "A=a {port}", "--jobs", "2", "--half-time", "60", "--sync", "--out", "/tmp/x", "--quiet",
                "--halves", "1", "--game-command", "g", "--round-robin"};
        assertEquals(List.of("--half-time", "60", "--sync", "--halves", "1"), ParallelTournament.matchArgs(argv));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> ParallelTournament.matchArgs(new String[] {"--jobs", "2", "--agent-port", "3500"}));
        assertTrue(e.getMessage().contains("--agent-port cannot be given with --jobs"), e.getMessage());

        List<Tournament.Fixture> fs = Tournament.schedule(List.of(TeamCommand.parse("A=x {port} 'q'"), TeamCommand.parse("B=y {port}")),
                "A", 2, false);
        assertEquals("game-01\tgame-01-A-vs-B\tA=x {port} 'q'\tB=y {port}\ngame-02\tgame-02-B-vs-A\tB=y {port}\tA=x {port} 'q'\n",
                ParallelTournament.jobsTable(fs));
        ParallelTournament.Plan plan = new ParallelTournament.Plan(fs, Path.of("/tmp/t o"), Path.of("/src"), "phalanx", "scripts/phalanx match",
                List.of("--half-time", "it's"), 2, null, 3, null, true);
        assertEquals("exec bash ~/'phalanx'/scripts/lib/tools/tournament-job {1} {2} {%} '/tmp/t o' 1 -- scripts/phalanx match --left {3} "
                + "--right {4} '--half-time' 'it'\\''s'", ParallelTournament.template(plan));
        List<String> c = ParallelTournament.command(plan);
        assertTrue(String.join(" ", c).contains("--joblog /tmp/t o/joblog --resume-failed --retries 3"), c.toString());
        assertTrue(c.containsAll(List.of("-S", ":")) && !c.contains("--return"), c.toString());
    }

    /** parallel takes 2/ in 2/h1 for h1's cores and runs --jobs there: a host's own N/ must win over --jobs. */
    @Test
    void aHostsOwnJobCountWinsOverJobs() throws IOException {
        Path hosts = tmp.resolve("hosts");
        Files.writeString(hosts, "# here and two others\n2/h1\nme@h2\n:\n");
        ParallelTournament.Plan plan = new ParallelTournament.Plan(List.of(), tmp.resolve("t"), Path.of("/src"), "phalanx", "g",
                List.of(), 3, hosts, 3, null, true);
        Files.createDirectories(plan.out());
        List<String> c = ParallelTournament.command(plan);
        assertEquals("# here and two others\n2/h1\n3/me@h2\n3/:\n", Files.readString(tmp.resolve("t/sshloginfile")));
        assertEquals("100%", c.get(c.indexOf("--jobs") + 1), c.toString());
        assertEquals(tmp.resolve("t/sshloginfile").toString(), c.get(c.indexOf("--sshloginfile") + 1));
    }

    @Test
    void portSlotsNeverShareAPort() {
        for (int s = 1; s < MatchOptions.MAX_PORT_SLOT; s++) {
            // slot s: agent ports [base, base+100), monitor ports [base+100, base+200)
            assertEquals(MatchOptions.slotBase(s) + 200, MatchOptions.slotBase(s + 1));
        }
        assertTrue(MatchOptions.slotBase(MatchOptions.MAX_PORT_SLOT) + 199 <= 65535);
        assertEquals(3500, MatchOptions.slotBase(1));
    }

    @Test
    void localJobsPlayEveryGameOnceInTheirOwnSlotsAndTheTablesAreTheSerialOnes() throws Exception {
        needParallel();
        Path out = tmp.resolve("t"), log = tmp.resolve("log"), ledger = tmp.resolve("ledger");
        Process p = tournament(log, Map.of("STAND_IN_SLEEP", "0.5", "STAND_IN_LEDGER", ledger.toString()),
                "--games", "2", "--round-robin", "--jobs", "2", "--out", out.toString(), "--quiet");
        assertEquals(0, finish(p), Files.readString(log));
        List<String[]> jl = joblog(out);
        assertEquals(6, jl.size(), Files.readString(out.resolve("joblog")));
        for (String[] l : jl) assertEquals("0", l[6].strip(), String.join(" ", l));
        assertEquals(once(6), ledger(ledger, "done"));
        // Two at a time: only slots 1 and 2, so two games never shared a port range.
        for (String l : Files.readAllLines(ledger)) {
            if (l.startsWith("start")) assertTrue(l.endsWith(" 1") || l.endsWith(" 2"), l);
        }
        for (int i = 1; i <= 6; i++) {
            assertTrue(Files.exists(out.resolve(Tournament.tag(i) + ".json")));
            assertTrue(Files.exists(out.resolve(Tournament.tag(i) + ".out")));
        }
        String text = Files.readString(log);
        assertTrue(text.contains("[6/6] "), text);
        assertTrue(text.contains("Games (6 in " + out + ")"), text);
        // The tables are those --report builds from the same files, as after a serial tournament.
        String tables = Files.readString(out.resolve("tables.md"));
        java.io.ByteArrayOutputStream again = new java.io.ByteArrayOutputStream();
        Tournament.report(out, null, new java.io.PrintStream(again, true));
        assertEquals(tables, Files.readString(out.resolve("tables.md")));
        assertTrue(tables.contains("| 1 | A | 1:0 | B | yes |"), tables);
    }

    @Test
    void hostsOverSshReturnTheFilesAndAGameThatFailsOnAHostIsRetriedAndRecorded() throws Exception {
        needParallel();
        assumeTrue(rsync(), "rsync is not installed: parallel's --return cannot be tested");
        Path out = tmp.resolve("t"), log = tmp.resolve("log"), ledger = tmp.resolve("ledger"), homes = tmp.resolve("hosts");
        Files.createDirectories(homes);
        Path hosts = tmp.resolve("hostfile");
        Files.writeString(hosts, "# two hosts that answer, one of them without a server, and one that is down\n1/h1\n1/h2\n1/dead\n");
        Map<String, String> env = new HashMap<>(Map.of("STAND_IN_SLEEP", "0.5", "STAND_IN_LEDGER", ledger.toString(),
                "FAKE_SSH_HOMES", homes.toString(), "STAND_IN_FAIL_ON", "h2"));
        Process p = tournament(log, env, "--games", "2", "--hosts", hosts.toString(), "--ssh", "bash " + RES.resolve("fake-ssh"),
                "--out", out.toString(), "--quiet");
        assertEquals(0, finish(p), Files.readString(log));
        List<String[]> jl = joblog(out);
        assertEquals(4, jl.size());
        for (String[] l : jl) {
            assertEquals("0", l[6].strip());
            assertEquals("h1", l[1], "only h1 can play: " + String.join(" ", l));
        }
        assertEquals(once(4), ledger(ledger, "done"));
        // Every game ran in h1's home and came back with --return; --cleanup removed the returned copies there.
        for (int i = 1; i <= 4; i++) {
            String tag = Tournament.tag(i);
            MatchResult r = MatchResult.read(out.resolve(tag + ".json"));
            assertTrue(r.completed());
            assertTrue(r.left().log().contains(homes.resolve("h1").toString()), r.left().log());
            assertTrue(Files.size(out.resolve(tag + ".out")) > 0);
            try (var s = Files.list(out)) {
                Path dir = s.filter(d -> d.getFileName().toString().startsWith(tag + "-")).findFirst().orElseThrow();
                assertTrue(Files.size(dir.resolve("monitor.log.gz")) > 0, dir.toString());
            }
        }
        assertFalse(Files.exists(homes.resolve("h1/phalanx-tournaments/t/game-01.json")));
        // The failed attempts: h2 has no server (exit 3), "dead" does not answer (255); each game that
        // went there was played on h1 instead.
        List<String> failures = Files.readAllLines(out.resolve("failures.log"));
        assertTrue(failures.stream().anyMatch(l -> l.contains("host=h2 exit=3")), failures.toString());
        assertTrue(failures.stream().anyMatch(l -> l.contains("host=dead exit=255")), failures.toString());
        Map<String, Long> startedOnH2 = Files.readAllLines(ledger).stream().map(l -> l.split(" "))
                .filter(f -> f[0].equals("start") && f[2].equals("h2")).collect(Collectors.groupingBy(f -> f[1], Collectors.counting()));
        assertFalse(startedOnH2.isEmpty(), Files.readString(ledger));
        for (String l : failures) {
            if (l.contains("host=h2")) assertTrue(startedOnH2.containsKey(l.split(" ")[1]), l);
        }
        assertTrue(Files.readString(log).contains("failed attempt(s) of a game on a host"), Files.readString(log));
    }

    @Test
    void aTournamentKilledInTheMiddleContinuesAndEveryGameIsPlayedOnce() throws Exception {
        killAndResume(false);
    }

    @Test
    void aTournamentOnHostsKilledInTheMiddleContinuesAndEveryGameIsPlayedOnce() throws Exception {
        assumeTrue(rsync(), "rsync is not installed: parallel's --return cannot be tested");
        killAndResume(true);
    }

    /**
     * 8 games 2 at a time, here or on two stand-in hosts; SIGTERM to the tournament (as `kill PID` does)
     * once two games are logged and two others are running; then the same command again.
     */
    private void killAndResume(boolean onHosts) throws Exception {
        needParallel();
        Path out = tmp.resolve("t"), log = tmp.resolve("log"), ledger = tmp.resolve("ledger"), homes = tmp.resolve("hosts");
        Files.createDirectories(homes);
        Map<String, String> env = Map.of("STAND_IN_SLEEP", "1.5", "STAND_IN_LEDGER", ledger.toString(), "FAKE_SSH_HOMES", homes.toString());
        List<String> a = new ArrayList<>(List.of("--games", "4", "--out", out.toString(), "--quiet"));
        if (onHosts) {
            Path hosts = tmp.resolve("hostfile");
            Files.writeString(hosts, "1/h1\n1/h2\n");
            a.addAll(List.of("--hosts", hosts.toString(), "--ssh", "bash " + RES.resolve("fake-ssh")));
        } else {
            a.addAll(List.of("--jobs", "2"));
        }
        String[] args = a.toArray(new String[0]);
        Process p = tournament(log, env, args);
        long deadline = System.nanoTime() + 60_000_000_000L;
        while (System.nanoTime() < deadline) {
            if (Files.exists(out.resolve("joblog")) && joblog(out).size() >= 2 && Files.exists(ledger)
                    && Files.readAllLines(ledger).stream().filter(l -> l.startsWith("start")).count() >= 4) break;
            Thread.sleep(50);
        }
        p.destroy();
        assertNotEquals(0, finish(p));
        int logged = joblog(out).size();
        assertTrue(logged >= 2 && logged < 8, "games logged at the kill: " + logged);
        // The stopped games end within parallel's --termseq (on a host, its remote wrapper stops them when
        // the connection is gone).
        long until = System.nanoTime() + 40_000_000_000L;
        while (ledger(ledger, "killed").size() + ledger(ledger, "done").size() < ledger(ledger, "start").size() && System.nanoTime() < until) {
            Thread.sleep(100);
        }
        Map<String, Long> killed = ledger(ledger, "killed");
        assertFalse(killed.isEmpty(), "no game was running at the kill: " + Files.readString(ledger));
        // Every game that started either ended or was stopped through its SIGTERM handler: none was cut off.
        java.util.Set<String> ended = new java.util.TreeSet<>(killed.keySet());
        ended.addAll(ledger(ledger, "done").keySet());
        assertEquals(ledger(ledger, "start").keySet(), ended, Files.readString(ledger));
        for (String tag : killed.keySet()) {
            // A stopped game is no result: the tables read only game-NN.json.
            assertFalse(Files.exists(out.resolve(tag + ".json")), tag);
            if (!onHosts) assertTrue(Files.exists(out.resolve(tag + ".failed.json")), tag);
        }

        Files.writeString(log, "--- again\n", java.nio.file.StandardOpenOption.APPEND);
        assertEquals(0, finish(tournament(log, env, args)), Files.readString(log));
        String text = Files.readString(log);
        assertTrue(text.contains("resuming " + out + ": " + logged + " of 8 games already played"), text);
        Map<Integer, Integer> seqs = new TreeMap<>();
        for (String[] l : joblog(out)) {
            assertEquals("0", l[6].strip(), String.join(" ", l));
            seqs.merge(Integer.parseInt(l[0]), 1, Integer::sum);
        }
        Map<Integer, Integer> all = new TreeMap<>();
        for (int i = 1; i <= 8; i++) all.put(i, 1);
        assertEquals(all, seqs, "each game once in the joblog");
        assertEquals(once(8), ledger(ledger, "done"), "each game played to its end exactly once: " + Files.readString(ledger));
        assertTrue(text.contains("Games (8 in " + out + ")"), text);
        for (int i = 1; i <= 8; i++) assertTrue(MatchResult.read(out.resolve(Tournament.tag(i) + ".json")).completed());
        if (!onHosts) {
            // A replayed game played in an empty folder; the stopped try's folder (no monitor log) stays beside it.
            for (String tag : killed.keySet()) {
                List<Path> dirs;
                try (var l = Files.list(out)) { dirs = l.filter(d -> d.getFileName().toString().startsWith(tag + "-")).sorted().toList(); }
                assertEquals(2, dirs.size(), dirs.toString());
                assertTrue(dirs.get(1).getFileName().toString().endsWith(".try-1"), dirs.toString());
                assertTrue(Files.exists(dirs.get(0).resolve("monitor.log.gz")), "the replay's folder has its game: " + dirs.get(0));
                assertFalse(Files.exists(dirs.get(1).resolve("monitor.log.gz")), "the stopped try's folder is its own: " + dirs.get(1));
            }
        }
    }

    @Test
    void aResumeWithOtherTeamsIsRefused() throws Exception {
        needParallel();
        Path out = tmp.resolve("t"), log = tmp.resolve("log");
        assertEquals(0, finish(tournament(log, Map.of("STAND_IN_SLEEP", "0"), "--jobs", "2", "--out", out.toString(), "--quiet")));
        assertEquals(2, finish(tournament(log, Map.of("STAND_IN_SLEEP", "0"), "--jobs", "2", "--out", out.toString(), "--games", "2")));
        assertTrue(Files.readString(log).contains("is from another tournament"), Files.readString(log));
    }
}
