"""`trimkit info`: JSON output, the human form, and error lines with exit status 2."""
import json
import subprocess

from conftest import TRIMKIT


def run(*args):
    return subprocess.run([TRIMKIT, *args], capture_output=True, text=True, timeout=120)


def test_info_json_on_bracket(bracket):
    result = run("info", bracket, "--json")
    assert result.returncode == 0, result.stderr
    info = json.loads(result.stdout)
    assert info["faces"] == 2 and info["loops"] == 3 and info["units"] == "mm"
    # plate: 4 natural-boundary lines + 1 hole circle; cylinder: 4 boundary lines
    assert info["coedges"] == 9
    assert isinstance(info["warnings"], list)
    assert info["unread_faces"] == 0


def test_info_counts_the_faces_the_reader_left_out(tmp_path):
    from iges_samples import write_skipped_face_file
    path, bad = write_skipped_face_file(tmp_path / "skipped_face.igs")
    info = json.loads(run("info", str(path), "--json").stdout)
    assert (info["faces"], info["unread_faces"]) == (1, 1)
    assert any(f"D{bad}" in w and "skipped" in w for w in info["warnings"])
    text = run("info", str(path)).stdout
    assert "faces:           1 (and 1 the reader left out: see the warnings)" in text


def test_info_text_on_bracket(bracket):
    result = run("info", bracket)
    assert result.returncode == 0
    assert "faces:" in result.stdout and "2" in result.stdout


def test_missing_file_is_bad_input(tmp_path):
    missing = tmp_path / "absent.igs"
    result = run("info", str(missing))
    assert result.returncode == 2
    assert result.stderr.startswith("trimkit: ") and "absent.igs" in result.stderr
    assert len(result.stderr.strip().splitlines()) == 1


def test_truncated_file_names_file_and_line(tmp_path, bracket):
    text = open(bracket).read().splitlines()
    truncated = tmp_path / "truncated.igs"
    truncated.write_text("\n".join(text[:len(text) // 2]) + "\n")
    result = run("info", str(truncated))
    assert result.returncode == 2
    assert "truncated.igs:" in result.stderr


def test_unknown_option_is_usage_error(bracket):
    result = run("info", bracket, "--bogus")
    assert result.returncode == 2 and "unknown option --bogus" in result.stderr


def test_unknown_extension(tmp_path):
    f = tmp_path / "part.xyz"
    f.write_text("x")
    result = run("info", str(f))
    assert result.returncode == 2 and "unsupported file type" in result.stderr
