-- expect-exit: 2
-- expect-output: <F> <LUA> .*sandbox_remove_outside\.lua:6: os\.rename cannot move '/nonexistent-aster-lite/a': a sandboxed study writes files only below its output folder .*sandbox_remove_outside \(a relative path is taken from there\) \(aster-lite --unsafe-lua lifts the sandbox\).*<F> <LUA> .*sandbox_remove_outside\.lua:7: os\.remove cannot delete '/nonexistent-aster-lite/b': a sandboxed study writes files only below its output folder
-- os.remove and os.rename change files: a sandboxed study changes files below
-- its output folder only (these paths do not exist, os.remove and os.rename
-- would merely fail on them without the sandbox).
pcall(os.rename, '/nonexistent-aster-lite/a', 'b')
os.remove('/nonexistent-aster-lite/b')
FIN{}
