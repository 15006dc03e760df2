# Sourced by run_w1.sh and run_w2.sh with 'root', 'peers' and 'scratch' set: installs Debian's
# lammps if missing and copies the peer decks to the scratch folder with their initial states.
if ! command -v lmp >/dev/null; then
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO=sudo
  $SUDO apt-get install -y -qq lammps >/dev/null
fi
rm -rf "$scratch" && cp -r "$peers" "$scratch"
/usr/bin/python3 "$scratch/common/gen.py" >/dev/null
