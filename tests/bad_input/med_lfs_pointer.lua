-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*med_lfs_pointer\.lua:5: .*med_lfs_pointer\.med: a Git LFS pointer, not the MED file itself \(fetch the file with 'git lfs pull'\)
-- The text pointer a repository cloned without Git LFS holds in a MED file's place.
DEBUT{}
MA = LIRE_MAILLAGE{FORMAT = 'MED', UNITE = 20}
FIN{}
