"""trimkit_batch's inputs and manifest without a cluster: which files a run converts and
where to, and what a rerun may skip."""
import dataclasses
import json
import os

import pytest

from trimkit_batch import inputs, manifest
from trimkit_batch.outcome import Outcome
from trimkit_batch.settings import Settings


def touch(path, text="x"):
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text)
    return path


def test_a_folder_keeps_its_tree_and_a_file_reached_twice_is_converted_once(tmp_path):
    a = touch(tmp_path / "lib" / "a.igs")
    b = touch(tmp_path / "lib" / "sub" / "b.STEP")
    touch(tmp_path / "lib" / "notes.txt")
    jobs = inputs.discover([tmp_path / "lib", a], tmp_path / "out", ".glb")
    assert [(j.input, j.output) for j in jobs] == [
        (str(a), str(tmp_path / "out" / "a.glb")), (str(b), str(tmp_path / "out" / "sub" / "b.glb"))]
    assert jobs[0].size == 1


@pytest.mark.parametrize("case, message", [("missing", "no such file"), ("text", "not a CAD file"),
                                           ("empty", "no CAD files"), ("collide", "would both be written")])
def test_bad_inputs_are_refused_naming_the_path(tmp_path, case, message):
    arguments = {"missing": [tmp_path / "gone.igs"], "text": [touch(tmp_path / "a.txt")],
                 "empty": [touch(tmp_path / "empty" / "a.txt").parent],
                 "collide": [touch(tmp_path / "p.igs"), touch(tmp_path / "p.stp")]}[case]
    with pytest.raises(inputs.InputError, match=message):
        inputs.discover(arguments, tmp_path / "out", ".glb")


def converted(tmp_path, settings=Settings()):
    source = touch(tmp_path / "in.igs", "model")
    [job] = inputs.discover([source], tmp_path / "out", settings.suffix)
    touch(tmp_path / "out" / "in.glb", "mesh!")
    sha = manifest.sha256_of(source)
    line = manifest.record(job, sha, settings, Outcome(status="ok", triangles=12, output_bytes=5))
    return job, sha, line


def test_a_rerun_skips_only_an_up_to_date_output(tmp_path):
    job, sha, line = converted(tmp_path)
    settings = Settings()
    assert list(line) == list(manifest.FIELDS)
    assert manifest.up_to_date(line, job, sha, settings)
    assert not manifest.up_to_date(None, job, sha, settings)
    assert not manifest.up_to_date(line, job, "0" * 64, settings)                        # input changed
    assert not manifest.up_to_date(line, job, sha, Settings(tolerance=0.002))            # settings changed
    assert not manifest.up_to_date(line, job, sha, Settings(check=True))
    assert not manifest.up_to_date(dict(line, status="failed"), job, sha, settings)     # never converted
    assert manifest.up_to_date(dict(line, status="skipped"), job, sha, settings)        # skipped last time too
    touch(tmp_path / "out" / "in.glb", "other mesh")                                     # output replaced
    assert not manifest.up_to_date(line, job, sha, settings)
    os.remove(tmp_path / "out" / "in.glb")                                               # output gone
    assert not manifest.up_to_date(line, job, sha, settings)


def test_the_skipped_line_keeps_the_figures(tmp_path):
    job, sha, line = converted(tmp_path)
    again = manifest.record(job, sha, Settings(), manifest.skipped(line))
    assert again["status"] == "skipped" and again["triangles"] == 12 and again["output_bytes"] == 5
    assert again["seconds"] == 0.0 and again["worker"] is None


def test_the_writer_replaces_the_old_manifest_and_a_torn_line_is_ignored(tmp_path):
    path = tmp_path / "manifest.jsonl"
    path.write_text(json.dumps({"input": "/old", "status": "ok"}) + "\n" + '{"input": "/torn", "sta')
    assert list(manifest.read(path)) == ["/old"]
    with manifest.Writer(path, [{"input": "/a", "status": "skipped"}]) as writer:
        assert [json.loads(l)["input"] for l in path.read_text().splitlines()] == ["/a"]
        writer.write({"input": "/b", "status": "ok"})
        assert manifest.read(path)["/b"]["status"] == "ok"  # on disk as soon as written
    assert list(manifest.read(path)) == ["/a", "/b"]
    assert sorted(os.listdir(tmp_path)) == ["manifest.jsonl"]


def test_settings_are_checked_and_stored_whole():
    assert Settings().as_dict() == dataclasses.asdict(Settings())
    with pytest.raises(ValueError, match="format"):
        Settings(format="fbx")
    with pytest.raises(ValueError, match="tolerance"):
        Settings(tolerance=0.0)
    with pytest.raises(ValueError, match="split parts"):
        Settings(format="blend", split="parts")


def test_a_face_the_reader_left_out_is_in_the_manifest_line(tmp_path):
    """The face missing from the output is listed with its reason (Model.unread_faces),
    as `trimkit mesh --json` lists it, and a skipped line keeps it."""
    from iges_samples import write_skipped_face_file
    from trimkit_batch import convert
    (tmp_path / "lib").mkdir()
    _, bad = write_skipped_face_file(tmp_path / "lib" / "skipped_face.igs")
    [job] = inputs.discover([tmp_path / "lib"], tmp_path / "out", ".ply")
    sha = manifest.sha256_of(job.input)
    outcome = convert.convert_file(job, sha, Settings())
    assert outcome.status == "ok", outcome.error
    [reason] = outcome.unread_faces
    assert f"D{bad}" in reason and "skipped" in reason
    line = manifest.record(job, sha, Settings(), outcome)
    assert line["unread_faces"] == [reason]
    assert manifest.record(job, sha, Settings(), manifest.skipped(line))["unread_faces"] == [reason]
